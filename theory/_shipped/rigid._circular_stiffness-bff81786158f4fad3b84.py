# ringchain generated code v1 sha256=2eb7699a07096f090462dc0ac3a85d423a4bce9278bdf78ff7646da9839437db
# derivation: rigid._circular_stiffness
# source key: 07201ab9dccdbac32795 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: A
# expression sha256: dc686fa25745de63a1271748cd05bde32569281aa73e3d2407a3be3c19743f80 (of its srepr)
def _lambdifygenerated(A):
    return (2/3)*numpy.sqrt(2)/numpy.sqrt(A)
