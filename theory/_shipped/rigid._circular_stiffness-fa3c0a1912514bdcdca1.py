# ringchain generated code v1 sha256=ef44ebcfbf037798c6e63a462542f8b1ef98952d9f7651232dc13c8efb4ec7b7
# derivation: rigid._circular_stiffness
# source key: 10a35615fa68ecdff34f (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: A
# expression sha256: dc686fa25745de63a1271748cd05bde32569281aa73e3d2407a3be3c19743f80 (of its srepr)
def _lambdifygenerated(A):
    return (2/3)*numpy.sqrt(2)/numpy.sqrt(A)
