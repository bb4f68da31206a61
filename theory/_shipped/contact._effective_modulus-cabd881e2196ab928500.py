# ringchain generated code v1 sha256=527e9e60f4d6fc2ada3387a03e63550fb8df0ffc4351e31a990952c470e92fa6
# derivation: contact._effective_modulus
# source key: 317867d47b5755454417 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: E, nu
# expression sha256: 242bd63f0d2cddcb2c6d7125a4195f50cf49f0fa9d1d926c8ba1a1974f8dbea5 (of its srepr)
def _lambdifygenerated(E, nu):
    return -1/2*E/((nu - 1)*(nu + 1))
