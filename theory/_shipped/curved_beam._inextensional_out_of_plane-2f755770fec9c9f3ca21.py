# ringchain generated code v1 sha256=c6fe0f93ab04baa28a9c396fa5706f3047c683e860160dbd39490539b0ce855b
# derivation: curved_beam._inextensional_out_of_plane
# source key: 0d3b9b67499038ff2889 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: k, R, r, E, nu, rho
# expression sha256: f48863f028ce55e00d94f6101b669c48786a55f46363a85bb921cca75f2eaa02 (of its srepr)
def _lambdifygenerated(k, R, r, E, nu, rho):
    return (1/2)*numpy.sqrt(E)*k*r*(k - 1)*(k + 1)/(R**2*numpy.sqrt(rho)*numpy.sqrt(k**2 + nu + 1))
