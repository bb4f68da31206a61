# ringchain generated code v1 sha256=61441ae31a342e51cea9ccc0e871a285ab6e2714ffb4ef546c49804aa5236236
# derivation: curved_beam._inextensional_out_of_plane
# source key: c0b268e8f55b26f011d3 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: k, R, r, E, nu, rho
# expression sha256: f48863f028ce55e00d94f6101b669c48786a55f46363a85bb921cca75f2eaa02 (of its srepr)
def _lambdifygenerated(k, R, r, E, nu, rho):
    return (1/2)*numpy.sqrt(E)*k*r*(k - 1)*(k + 1)/(R**2*numpy.sqrt(rho)*numpy.sqrt(k**2 + nu + 1))
