# ringchain generated code v1 sha256=899da05b47ab4b2a62c95e4892fcf3c70e1db71cd70a64195610130f1af00f1a
# derivation: curved_beam._inextensional_out_of_plane
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: k, R, r, E, nu, rho
# expression sha256: f48863f028ce55e00d94f6101b669c48786a55f46363a85bb921cca75f2eaa02 (of its srepr)
def _lambdifygenerated(k, R, r, E, nu, rho):
    return (1/2)*numpy.sqrt(E)*k*r*(k - 1)*(k + 1)/(R**2*numpy.sqrt(rho)*numpy.sqrt(k**2 + nu + 1))
