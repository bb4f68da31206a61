# ringchain generated code v1 sha256=0c418435b46ce3ff3814201903fc57e5191f8c55fe0c348629af1b0749fda52f
# derivation: attenuation._attenuation_length
# source key: 317867d47b5755454417 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: n, a, sigma_Z
# expression sha256: c006f1ce24c0adab1e8a4c6bcc5c7f23bb75a58176f89fd31cdb04dd7d590c42 (of its srepr)
def _lambdifygenerated(n, a, sigma_Z):
    return (1/24)*a*(n - 5)*(n + 1)**2/(sigma_Z**2*(1 - n))
