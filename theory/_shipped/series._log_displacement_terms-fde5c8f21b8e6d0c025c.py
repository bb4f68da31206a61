# ringchain generated code v1 sha256=6293ca81c8fb2bacc7c17a184541d42ae2d3b9d56c05016a9e18bbf38f6db4e7
# derivation: series._log_displacement_terms
# source key: 263ab3517922b3fc21eb (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F, K_c, K_b
# expression sha256: 98696c8a9e8445191718c5e056aa6ba5b6a39d4f468a6cba1e7af28e4627c5c2 (of its srepr)
def _lambdifygenerated(F, K_c, K_b):
    x0 = numpy.log(F)
    return (x0 - numpy.log(K_b), (2/3)*x0 - 2/3*numpy.log(K_c),)
