# ringchain generated code v1 sha256=d377f641870c688f0078527fc5c4c07e5f220ba1753b0e0393b303b18d15a5f0
# derivation: contact._stiffness_circular
# source key: f3be020559998432f519 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R, r, E, nu
# expression sha256: 920a494dfcb3c4248839e1ae44a064f5427170dbad03d63efe968de526cc255c (of its srepr)
def _lambdifygenerated(R, r, E, nu):
    return ((2/3)*E/((1 - nu)*(nu + 1)), numpy.sqrt(r)*numpy.sqrt((R - r)/(R - 2*r)),)
