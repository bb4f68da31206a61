# ringchain generated code v1 sha256=f58a5e11539b07ed073fe7afc0021d4b6655cea6c2e4fee1e81b5f0930b0de2b
# derivation: contact._effective_modulus
# source key: 10a35615fa68ecdff34f (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: E, nu
# expression sha256: 242bd63f0d2cddcb2c6d7125a4195f50cf49f0fa9d1d926c8ba1a1974f8dbea5 (of its srepr)
def _lambdifygenerated(E, nu):
    return -1/2*E/((nu - 1)*(nu + 1))
