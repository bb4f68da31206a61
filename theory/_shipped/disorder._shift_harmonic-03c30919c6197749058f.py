# ringchain generated code v1 sha256=755910691403b159347131948f7f143810479457a0ec096252711dd0e342e807
# derivation: disorder._shift_harmonic
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: n, sigma_K, sigma_m, rho_mK
# expression sha256: 94186ae1566d4a5a5b234d286e82a99d2f169df14c98d421734551c59c91c2e5 (of its srepr)
def _lambdifygenerated(n, sigma_K, sigma_m, rho_mK):
    x0 = sigma_K**2
    x1 = (1/4)/n
    return rho_mK*sigma_K*sigma_m*x1 + (1/8)*sigma_m**2 - x0*x1 - 1/8*x0/n**2
