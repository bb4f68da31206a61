# ringchain generated code v1 sha256=a9948f3fb9b59162883ff4b9893de9eab94403415b7c163e9be413b0bb7acbb8
# derivation: rigid._circular_stiffness
# source key: 0881d513a06819d2e367 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: A
# expression sha256: dc686fa25745de63a1271748cd05bde32569281aa73e3d2407a3be3c19743f80 (of its srepr)
def _lambdifygenerated(A):
    return (2/3)*numpy.sqrt(2)/numpy.sqrt(A)
