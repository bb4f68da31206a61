# ringchain generated code v1 sha256=7125af4606d05eab639b4520743485aeba9e4ce961dbe2edaa498c6e9da01547
# derivation: rigid._circular_stiffness
# source key: 0d3b9b67499038ff2889 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: A
# expression sha256: dc686fa25745de63a1271748cd05bde32569281aa73e3d2407a3be3c19743f80 (of its srepr)
def _lambdifygenerated(A):
    return (2/3)*numpy.sqrt(2)/numpy.sqrt(A)
