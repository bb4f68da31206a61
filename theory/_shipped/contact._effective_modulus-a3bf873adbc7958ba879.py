# ringchain generated code v1 sha256=fc2dbc41002e0691e662d7f611b0d908d68b1168eaba4f4f6170bde423497070
# derivation: contact._effective_modulus
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: E, nu
# expression sha256: 242bd63f0d2cddcb2c6d7125a4195f50cf49f0fa9d1d926c8ba1a1974f8dbea5 (of its srepr)
def _lambdifygenerated(E, nu):
    return -1/2*E/((nu - 1)*(nu + 1))
