# ringchain generated code v1 sha256=8a98931a0ef164dc4455ecb171ed5f7be8475fbb44f27acd37ee2b9732e0fa82
# derivation: scattering._localization_length
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: omega, m, k, a, sigma_m, sigma_k, rho
# expression sha256: 1d2ef51298e53587d1775996cdc866380ca4f0dff04bf581b03f4382f8994a0e (of its srepr)
def _lambdifygenerated(omega, m, k, a, sigma_m, sigma_k, rho):
    x0 = omega**2
    x1 = m*x0/k
    x2 = (1/2)*rho*(1 - 1/2*x1)
    x3 = (1/2 - x2)*(-sigma_k + sigma_m)**2 + (sigma_k + sigma_m)**2*(x2 + 1/2)
    return (4*a*k*(1 - 1/4*x1)/(m*x0*x3), x3)
