# ringchain generated code v1 sha256=92965c5b6166d32b06f1f32b92652c9e50ea9cb410a060d887fa4843c3ef81c0
# derivation: rigid._circular_stiffness
# source key: 263ab3517922b3fc21eb (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: A
# expression sha256: dc686fa25745de63a1271748cd05bde32569281aa73e3d2407a3be3c19743f80 (of its srepr)
def _lambdifygenerated(A):
    return (2/3)*numpy.sqrt(2)/numpy.sqrt(A)
