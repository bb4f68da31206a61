# ringchain generated code v1 sha256=5d911a8cb8616ef0e2dc3f7a295ff8929f5a8cedfb8a053d08db33c8a15a133d
# derivation: rigid._circular_stiffness
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: A
# expression sha256: dc686fa25745de63a1271748cd05bde32569281aa73e3d2407a3be3c19743f80 (of its srepr)
def _lambdifygenerated(A):
    return (2/3)*numpy.sqrt(2)/numpy.sqrt(A)
