# ringchain generated code v1 sha256=562559c265d74905a489e5eaef2efc3eeb944805005631bcd2355a895d1ac3c8
# derivation: contact._effective_modulus
# source key: 0881d513a06819d2e367 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: E, nu
# expression sha256: 242bd63f0d2cddcb2c6d7125a4195f50cf49f0fa9d1d926c8ba1a1974f8dbea5 (of its srepr)
def _lambdifygenerated(E, nu):
    return -1/2*E/((nu - 1)*(nu + 1))
