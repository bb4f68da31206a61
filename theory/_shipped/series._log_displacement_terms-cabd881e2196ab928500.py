# ringchain generated code v1 sha256=b04ee6f4415ea7b1abaf3a9dba6270e81e5a136ce022240d53ffb8d0af58d88b
# derivation: series._log_displacement_terms
# source key: 317867d47b5755454417 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F, K_c, K_b
# expression sha256: 98696c8a9e8445191718c5e056aa6ba5b6a39d4f468a6cba1e7af28e4627c5c2 (of its srepr)
def _lambdifygenerated(F, K_c, K_b):
    x0 = numpy.log(F)
    return (x0 - numpy.log(K_b), (2/3)*x0 - 2/3*numpy.log(K_c),)
