# ringchain generated code v1 sha256=de70c876446cf904066a9ba1e918ea3fb1220953ac43def9702f1744fd88d90d
# derivation: curved_beam._inextensional_in_plane
# source key: a22a0557fcec1bc1abe9 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: k, R, r, E, nu, rho
# expression sha256: 268afb1bf318f0a04178ef97b41cbc44d5619516d7e3f927661309fad15ecf03 (of its srepr)
def _lambdifygenerated(k, R, r, E, nu, rho):
    return (1/2)*numpy.sqrt(E)*k*r*(k - 1)*(k + 1)/(R**2*numpy.sqrt(rho)*numpy.sqrt(k**2 + 1))
