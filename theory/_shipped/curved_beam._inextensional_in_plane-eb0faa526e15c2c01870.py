# ringchain generated code v1 sha256=aa39242b1e376905113727ad2d637367c2ed9afe5ef7da00203989804280dd34
# derivation: curved_beam._inextensional_in_plane
# source key: c0b268e8f55b26f011d3 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: k, R, r, E, nu, rho
# expression sha256: 268afb1bf318f0a04178ef97b41cbc44d5619516d7e3f927661309fad15ecf03 (of its srepr)
def _lambdifygenerated(k, R, r, E, nu, rho):
    return (1/2)*numpy.sqrt(E)*k*r*(k - 1)*(k + 1)/(R**2*numpy.sqrt(rho)*numpy.sqrt(k**2 + 1))
