# ringchain generated code v1 sha256=1165eac9e2d4e06dda369fd863414185f9f4382b762fad97f3d5ff5f2476eefc
# derivation: attenuation._attenuation_length
# source key: c0b268e8f55b26f011d3 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: n, a, sigma_Z
# expression sha256: c006f1ce24c0adab1e8a4c6bcc5c7f23bb75a58176f89fd31cdb04dd7d590c42 (of its srepr)
def _lambdifygenerated(n, a, sigma_Z):
    return (1/24)*a*(n - 5)*(n + 1)**2/(sigma_Z**2*(1 - n))
