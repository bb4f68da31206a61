# ringchain generated code v1 sha256=daa2eb70e75327cb65014c601b00eb378a27d2ed985ae0ab9d83c851aedc7559
# derivation: contact._effective_modulus
# source key: 263ab3517922b3fc21eb (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: E, nu
# expression sha256: 242bd63f0d2cddcb2c6d7125a4195f50cf49f0fa9d1d926c8ba1a1974f8dbea5 (of its srepr)
def _lambdifygenerated(E, nu):
    return -1/2*E/((nu - 1)*(nu + 1))
