# ringchain generated code v1 sha256=43d3842114a4f89ebaafab8e90f12c6c61f5ef26c49a1c0338605647aff42ff0
# derivation: attenuation._attenuation_length
# source key: aaa6be78b00d30412b2b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: n, a, sigma_Z
# expression sha256: c006f1ce24c0adab1e8a4c6bcc5c7f23bb75a58176f89fd31cdb04dd7d590c42 (of its srepr)
def _lambdifygenerated(n, a, sigma_Z):
    return (1/24)*a*(n - 5)*(n + 1)**2/(sigma_Z**2*(1 - n))
