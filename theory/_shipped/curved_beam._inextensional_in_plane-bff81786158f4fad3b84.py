# ringchain generated code v1 sha256=274b27311cef6d2ad77d2d90966409a370ada40c4bbd5a1988b383af44886fed
# derivation: curved_beam._inextensional_in_plane
# source key: 07201ab9dccdbac32795 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: k, R, r, E, nu, rho
# expression sha256: 268afb1bf318f0a04178ef97b41cbc44d5619516d7e3f927661309fad15ecf03 (of its srepr)
def _lambdifygenerated(k, R, r, E, nu, rho):
    return (1/2)*numpy.sqrt(E)*k*r*(k - 1)*(k + 1)/(R**2*numpy.sqrt(rho)*numpy.sqrt(k**2 + 1))
