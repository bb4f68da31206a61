# ringchain generated code v1 sha256=e746361caba9aa5f591699894f660ab079d00fc0759774eff858a3eae37a104b
# derivation: series._log_displacement_terms
# source key: 10a35615fa68ecdff34f (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F, K_c, K_b
# expression sha256: 98696c8a9e8445191718c5e056aa6ba5b6a39d4f468a6cba1e7af28e4627c5c2 (of its srepr)
def _lambdifygenerated(F, K_c, K_b):
    x0 = numpy.log(F)
    return (x0 - numpy.log(K_b), (2/3)*x0 - 2/3*numpy.log(K_c),)
