# ringchain generated code v1 sha256=71dbf88e64e68b95f768f961f4f03df9d54fdcb516cd9cc00b1ce5e8b70f17ed
# derivation: contact._effective_modulus
# source key: 0d3b9b67499038ff2889 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: E, nu
# expression sha256: 242bd63f0d2cddcb2c6d7125a4195f50cf49f0fa9d1d926c8ba1a1974f8dbea5 (of its srepr)
def _lambdifygenerated(E, nu):
    return -1/2*E/((nu - 1)*(nu + 1))
