# ringchain generated code v1 sha256=1af1f3de75c4519299e2d8271f106c97452424ecc500a3b1b30c8c62c5b1bdbd
# derivation: series._log_displacement_terms
# source key: caeff341571871d5b69b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F, K_c, K_b
# expression sha256: 98696c8a9e8445191718c5e056aa6ba5b6a39d4f468a6cba1e7af28e4627c5c2 (of its srepr)
def _lambdifygenerated(F, K_c, K_b):
    x0 = numpy.log(F)
    return (x0 - numpy.log(K_b), (2/3)*x0 - 2/3*numpy.log(K_c),)
