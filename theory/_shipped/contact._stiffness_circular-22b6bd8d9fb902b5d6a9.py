# ringchain generated code v1 sha256=f65ea13dc7cde287db08b8888ff9229b2da08c5644fc163c27a113a4dce03e9b
# derivation: contact._stiffness_circular
# source key: 0881d513a06819d2e367 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r, E, nu
# expression sha256: 920a494dfcb3c4248839e1ae44a064f5427170dbad03d63efe968de526cc255c (of its srepr)
def _lambdifygenerated(R, r, E, nu):
    return ((2/3)*E/((1 - nu)*(nu + 1)), numpy.sqrt(r)*numpy.sqrt((R - r)/(R - 2*r)),)
