# ringchain generated code v1 sha256=2900885bc1215d36d798b17b5e2b1f67898a1ad455ce11afff57b4fda09f26cd
# derivation: scattering._impedance_spread
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: n, sigma_K, sigma_m, rho_mK
# expression sha256: 6606cd05ff7da72ac5ff27539ae1eb52a2bee96b67ba2da5194b8b7ca82f32b9 (of its srepr)
def _lambdifygenerated(n, sigma_K, sigma_m, rho_mK):
    x0 = (1/2)*rho_mK
    x1 = sigma_K/n
    return (1/2)*numpy.sqrt((1/2 - x0)*(sigma_m - x1)**2 + (sigma_m + x1)**2*(x0 + 1/2))
