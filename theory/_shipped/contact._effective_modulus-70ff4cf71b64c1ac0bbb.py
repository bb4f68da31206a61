# ringchain generated code v1 sha256=bdd4eb49c9f67ea9b3e780ea204cc96e6d470bfc1c9509f9a4e7cdf68e4a594c
# derivation: contact._effective_modulus
# source key: a22a0557fcec1bc1abe9 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: E, nu
# expression sha256: 242bd63f0d2cddcb2c6d7125a4195f50cf49f0fa9d1d926c8ba1a1974f8dbea5 (of its srepr)
def _lambdifygenerated(E, nu):
    return -1/2*E/((nu - 1)*(nu + 1))
