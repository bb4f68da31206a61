# ringchain generated code v1 sha256=33f04dc1a34045fe2f30f63c9c0639e1a828f5bd8b6dd1eb2c098f8ef2b78a8d
# derivation: curved_beam._inextensional_in_plane
# source key: 263ab3517922b3fc21eb (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: k, R, r, E, nu, rho
# expression sha256: 268afb1bf318f0a04178ef97b41cbc44d5619516d7e3f927661309fad15ecf03 (of its srepr)
def _lambdifygenerated(k, R, r, E, nu, rho):
    return (1/2)*numpy.sqrt(E)*k*r*(k - 1)*(k + 1)/(R**2*numpy.sqrt(rho)*numpy.sqrt(k**2 + 1))
