# ringchain generated code v1 sha256=b019b9b044fff03f107a607a6252158665bf2645856a16cd62ff6a287f42afd8
# derivation: contact._effective_modulus
# source key: caeff341571871d5b69b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: E, nu
# expression sha256: 242bd63f0d2cddcb2c6d7125a4195f50cf49f0fa9d1d926c8ba1a1974f8dbea5 (of its srepr)
def _lambdifygenerated(E, nu):
    return -1/2*E/((nu - 1)*(nu + 1))
