# ringchain generated code v1 sha256=bcb78adcb2dea703326d47f0fdbc4a6e0ab261ad3ff5e5c0f1a15ac8a4eda2f5
# derivation: rigid._circular_stiffness
# source key: f3be020559998432f519 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: A
# expression sha256: dc686fa25745de63a1271748cd05bde32569281aa73e3d2407a3be3c19743f80 (of its srepr)
def _lambdifygenerated(A):
    return (2/3)*numpy.sqrt(2)/numpy.sqrt(A)
