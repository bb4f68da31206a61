# ringchain generated code v1 sha256=16d173f5eef34ea1937ed3ab5bf4a0eb344fa03a979b0b157d5552d2968b10c3
# derivation: rigid._circular_stiffness
# source key: aaa6be78b00d30412b2b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: A
# expression sha256: dc686fa25745de63a1271748cd05bde32569281aa73e3d2407a3be3c19743f80 (of its srepr)
def _lambdifygenerated(A):
    return (2/3)*numpy.sqrt(2)/numpy.sqrt(A)
