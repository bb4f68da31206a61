# ringchain generated code v1 sha256=d7efe6832a21fb9f884c7201f26efccd8d1ee40c948e0779bdcd46dcd27cf7d8
# derivation: attenuation._attenuation_length
# source key: a22a0557fcec1bc1abe9 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: n, a, sigma_Z
# expression sha256: c006f1ce24c0adab1e8a4c6bcc5c7f23bb75a58176f89fd31cdb04dd7d590c42 (of its srepr)
def _lambdifygenerated(n, a, sigma_Z):
    return (1/24)*a*(n - 5)*(n + 1)**2/(sigma_Z**2*(1 - n))
