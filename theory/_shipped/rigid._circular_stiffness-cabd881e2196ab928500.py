# ringchain generated code v1 sha256=f7d07a1d41a75cc755e708ed5457e5f554529bf208eb9137aec2bf366a8b5035
# derivation: rigid._circular_stiffness
# source key: 317867d47b5755454417 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: A
# expression sha256: dc686fa25745de63a1271748cd05bde32569281aa73e3d2407a3be3c19743f80 (of its srepr)
def _lambdifygenerated(A):
    return (2/3)*numpy.sqrt(2)/numpy.sqrt(A)
