# ringchain generated code v1 sha256=d1e15d2992929a4b3cdc0c1f4d6b3d3e3dbd50328331d2cc4a3997d94fa78ff7
# derivation: attenuation._attenuation_length
# source key: 0881d513a06819d2e367 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: n, a, sigma_Z
# expression sha256: c006f1ce24c0adab1e8a4c6bcc5c7f23bb75a58176f89fd31cdb04dd7d590c42 (of its srepr)
def _lambdifygenerated(n, a, sigma_Z):
    return (1/24)*a*(n - 5)*(n + 1)**2/(sigma_Z**2*(1 - n))
