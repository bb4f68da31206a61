# ringchain generated code v1 sha256=1c38574d83534882ccaa4c5aedd74dd2d4362bcc69ca96b1b8447943478f3056
# derivation: scattering._localization_length
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: omega, m, k, a, sigma_m, sigma_k, rho
# expression sha256: 1d2ef51298e53587d1775996cdc866380ca4f0dff04bf581b03f4382f8994a0e (of its srepr)
def _lambdifygenerated(omega, m, k, a, sigma_m, sigma_k, rho):
    x0 = omega**2
    x1 = m*x0/k
    x2 = (1/2)*rho*(1 - 1/2*x1)
    x3 = (1/2 - x2)*(-sigma_k + sigma_m)**2 + (sigma_k + sigma_m)**2*(x2 + 1/2)
    return (4*a*k*(1 - 1/4*x1)/(m*x0*x3), x3)
