# ringchain generated code v1 sha256=ca7d32925f76b0505e100e43f8bcc2967f200402438e20c8459dea9b182cf985
# derivation: contact._stiffness_circular
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r, E, nu
# expression sha256: 920a494dfcb3c4248839e1ae44a064f5427170dbad03d63efe968de526cc255c (of its srepr)
def _lambdifygenerated(R, r, E, nu):
    return ((2/3)*E/((1 - nu)*(nu + 1)), numpy.sqrt(r)*numpy.sqrt((R - r)/(R - 2*r)),)
