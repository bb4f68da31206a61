# ringchain generated code v1 sha256=efaae3ab252cc66600edec1f67c5a64fc0bb1788409eca85a8e806426250e6f2
# derivation: rigid._circular_stiffness
# source key: c0b268e8f55b26f011d3 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: A
# expression sha256: dc686fa25745de63a1271748cd05bde32569281aa73e3d2407a3be3c19743f80 (of its srepr)
def _lambdifygenerated(A):
    return (2/3)*numpy.sqrt(2)/numpy.sqrt(A)
