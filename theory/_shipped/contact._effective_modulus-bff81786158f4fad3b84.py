# ringchain generated code v1 sha256=b45e14d037d3526841d82c40527d5a11e39502c59c9ee66cf6d925bab88dcc74
# derivation: contact._effective_modulus
# source key: 07201ab9dccdbac32795 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: E, nu
# expression sha256: 242bd63f0d2cddcb2c6d7125a4195f50cf49f0fa9d1d926c8ba1a1974f8dbea5 (of its srepr)
def _lambdifygenerated(E, nu):
    return -1/2*E/((nu - 1)*(nu + 1))
