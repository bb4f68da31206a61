# ringchain generated code v1 sha256=ca526e26bc58a938e56bcdf6965157bbb44484bc54a30a5bf930cf9e7221cb66
# derivation: rigid._circular_stiffness
# source key: a22a0557fcec1bc1abe9 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: A
# expression sha256: dc686fa25745de63a1271748cd05bde32569281aa73e3d2407a3be3c19743f80 (of its srepr)
def _lambdifygenerated(A):
    return (2/3)*numpy.sqrt(2)/numpy.sqrt(A)
