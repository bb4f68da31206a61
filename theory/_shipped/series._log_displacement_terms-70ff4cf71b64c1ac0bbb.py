# ringchain generated code v1 sha256=a0bee252531eb9cbb6432e46017dd9e3e27cc9f1dcce8b8d2ed1a5fd05d94c41
# derivation: series._log_displacement_terms
# source key: a22a0557fcec1bc1abe9 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F, K_c, K_b
# expression sha256: 98696c8a9e8445191718c5e056aa6ba5b6a39d4f468a6cba1e7af28e4627c5c2 (of its srepr)
def _lambdifygenerated(F, K_c, K_b):
    x0 = numpy.log(F)
    return (x0 - numpy.log(K_b), (2/3)*x0 - 2/3*numpy.log(K_c),)
