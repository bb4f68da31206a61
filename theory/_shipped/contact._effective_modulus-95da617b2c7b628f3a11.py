# ringchain generated code v1 sha256=c1c258617c5a2e6815c94c9a0954f87707374878e856977198f7b1c92ba6f16a
# derivation: contact._effective_modulus
# source key: f3be020559998432f519 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: E, nu
# expression sha256: 242bd63f0d2cddcb2c6d7125a4195f50cf49f0fa9d1d926c8ba1a1974f8dbea5 (of its srepr)
def _lambdifygenerated(E, nu):
    return -1/2*E/((nu - 1)*(nu + 1))
