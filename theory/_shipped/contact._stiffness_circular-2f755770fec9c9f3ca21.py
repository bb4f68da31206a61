# ringchain generated code v1 sha256=7210a92b7257bc5758f21023fc2f0974e0ae231fdfc3cf99a6daeb223f72aa48
# derivation: contact._stiffness_circular
# source key: 0d3b9b67499038ff2889 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r, E, nu
# expression sha256: 920a494dfcb3c4248839e1ae44a064f5427170dbad03d63efe968de526cc255c (of its srepr)
def _lambdifygenerated(R, r, E, nu):
    return ((2/3)*E/((1 - nu)*(nu + 1)), numpy.sqrt(r)*numpy.sqrt((R - r)/(R - 2*r)),)
