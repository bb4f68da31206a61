# ringchain generated code v1 sha256=1d8694456d6fbb1f143cb493e851d39aa8a64c49214f09a80d8384e5b5616019
# derivation: scattering._localization_length
# source key: a22a0557fcec1bc1abe9 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: omega, m, k, a, sigma_m, sigma_k, rho
# expression sha256: 1d2ef51298e53587d1775996cdc866380ca4f0dff04bf581b03f4382f8994a0e (of its srepr)
def _lambdifygenerated(omega, m, k, a, sigma_m, sigma_k, rho):
    x0 = omega**2
    x1 = m*x0/k
    x2 = (1/2)*rho*(1 - 1/2*x1)
    x3 = (1/2 - x2)*(-sigma_k + sigma_m)**2 + (sigma_k + sigma_m)**2*(x2 + 1/2)
    return (4*a*k*(1 - 1/4*x1)/(m*x0*x3), x3)
