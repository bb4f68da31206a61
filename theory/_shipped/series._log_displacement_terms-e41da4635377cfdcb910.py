# ringchain generated code v1 sha256=27f7762359938099e7f87ab0f8cb0b189b495e9a523dccc713742d377e646a61
# derivation: series._log_displacement_terms
# source key: aaa6be78b00d30412b2b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F, K_c, K_b
# expression sha256: 98696c8a9e8445191718c5e056aa6ba5b6a39d4f468a6cba1e7af28e4627c5c2 (of its srepr)
def _lambdifygenerated(F, K_c, K_b):
    x0 = numpy.log(F)
    return (x0 - numpy.log(K_b), (2/3)*x0 - 2/3*numpy.log(K_c),)
