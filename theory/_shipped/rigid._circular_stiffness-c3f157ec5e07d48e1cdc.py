# ringchain generated code v1 sha256=a295275107be7f2e155f86a1e58e587ff53bc9b220cadde0de4da6b316c64a6a
# derivation: rigid._circular_stiffness
# source key: caeff341571871d5b69b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: A
# expression sha256: dc686fa25745de63a1271748cd05bde32569281aa73e3d2407a3be3c19743f80 (of its srepr)
def _lambdifygenerated(A):
    return (2/3)*numpy.sqrt(2)/numpy.sqrt(A)
