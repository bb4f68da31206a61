# ringchain generated code v1 sha256=45235700da5021b25fafacdbe702c1d8be68a4bd7bd87169ea4e47138d1d1801
# derivation: curved_beam._inextensional_in_plane
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: k, R, r, E, nu, rho
# expression sha256: 268afb1bf318f0a04178ef97b41cbc44d5619516d7e3f927661309fad15ecf03 (of its srepr)
def _lambdifygenerated(k, R, r, E, nu, rho):
    return (1/2)*numpy.sqrt(E)*k*r*(k - 1)*(k + 1)/(R**2*numpy.sqrt(rho)*numpy.sqrt(k**2 + 1))
