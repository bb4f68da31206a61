# ringchain generated code v1 sha256=24f5db96c0bebf465f27e0075d6e37dd67ddbb15979f235e604d07ab081e8f53
# derivation: contact._effective_modulus
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: E, nu
# expression sha256: 242bd63f0d2cddcb2c6d7125a4195f50cf49f0fa9d1d926c8ba1a1974f8dbea5 (of its srepr)
def _lambdifygenerated(E, nu):
    return -1/2*E/((nu - 1)*(nu + 1))
