# ringchain generated code v1 sha256=b60442c8a6c5b43fa5b96eeb79446e4e062917260184d35ae98866366ddf2f47
# derivation: series._log_displacement_terms
# source key: 0d3b9b67499038ff2889 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F, K_c, K_b
# expression sha256: 98696c8a9e8445191718c5e056aa6ba5b6a39d4f468a6cba1e7af28e4627c5c2 (of its srepr)
def _lambdifygenerated(F, K_c, K_b):
    x0 = numpy.log(F)
    return (x0 - numpy.log(K_b), (2/3)*x0 - 2/3*numpy.log(K_c),)
