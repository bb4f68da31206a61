# ringchain generated code v1 sha256=3d667ee893a95f0ac87f8db982cfebb0838994a598a0862454b3c6ef4a33356b
# derivation: curved_beam._inextensional_in_plane
# source key: 317867d47b5755454417 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: k, R, r, E, nu, rho
# expression sha256: 268afb1bf318f0a04178ef97b41cbc44d5619516d7e3f927661309fad15ecf03 (of its srepr)
def _lambdifygenerated(k, R, r, E, nu, rho):
    return (1/2)*numpy.sqrt(E)*k*r*(k - 1)*(k + 1)/(R**2*numpy.sqrt(rho)*numpy.sqrt(k**2 + 1))
