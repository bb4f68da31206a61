# ringchain generated code v1 sha256=1a7fa9ac8828d81be53e4b016467d959bc2c4406701563d56584e6bb57ef2eba
# derivation: scattering._impedance_spread
# source key: 317867d47b5755454417 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: n, sigma_K, sigma_m, rho_mK
# expression sha256: 6606cd05ff7da72ac5ff27539ae1eb52a2bee96b67ba2da5194b8b7ca82f32b9 (of its srepr)
def _lambdifygenerated(n, sigma_K, sigma_m, rho_mK):
    x0 = (1/2)*rho_mK
    x1 = sigma_K/n
    return (1/2)*numpy.sqrt((1/2 - x0)*(sigma_m - x1)**2 + (sigma_m + x1)**2*(x0 + 1/2))
