# ringchain generated code v1 sha256=fe90ea573a81c6d84526614b7d35997e00c10d1931270242e108c2bd788aec4e
# derivation: contact._stiffness_circular
# source key: caeff341571871d5b69b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r, E, nu
# expression sha256: 920a494dfcb3c4248839e1ae44a064f5427170dbad03d63efe968de526cc255c (of its srepr)
def _lambdifygenerated(R, r, E, nu):
    return ((2/3)*E/((1 - nu)*(nu + 1)), numpy.sqrt(r)*numpy.sqrt((R - r)/(R - 2*r)),)
