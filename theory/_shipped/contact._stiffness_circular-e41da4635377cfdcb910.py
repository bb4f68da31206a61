# ringchain generated code v1 sha256=9d49405e877dce1e01969e3efb4e543d041a82db03eadd6b18313505c93c18d8
# derivation: contact._stiffness_circular
# source key: aaa6be78b00d30412b2b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r, E, nu
# expression sha256: 920a494dfcb3c4248839e1ae44a064f5427170dbad03d63efe968de526cc255c (of its srepr)
def _lambdifygenerated(R, r, E, nu):
    return ((2/3)*E/((1 - nu)*(nu + 1)), numpy.sqrt(r)*numpy.sqrt((R - r)/(R - 2*r)),)
