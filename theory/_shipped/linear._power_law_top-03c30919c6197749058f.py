# ringchain generated code v1 sha256=fc6cff91ea45c73c5b1f3f9c965cee09ba53ba2d5001975385232934cfdedda9
# derivation: linear._power_law_top
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F_0, K, n, m
# expression sha256: 1608b90f5fab4fef0955b1d13283288848aad2698d39d3b6ad3eb3bc667dd20c (of its srepr)
def _lambdifygenerated(F_0, K, n, m):
    x0 = (1/2)/n
    return 2*F_0**(1/2 - x0)*K**x0*numpy.sqrt(n)/numpy.sqrt(m)
