# ringchain generated code v1 sha256=fe1b43dbe1c30f7d9f206abefe045ffea5478a42b565d777fadd36ece7340177
# derivation: rigid._circular_stiffness
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: A
# expression sha256: dc686fa25745de63a1271748cd05bde32569281aa73e3d2407a3be3c19743f80 (of its srepr)
def _lambdifygenerated(A):
    return (2/3)*numpy.sqrt(2)/numpy.sqrt(A)
