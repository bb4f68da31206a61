# ringchain generated code v1 sha256=5452b2b98c6ee4517912e0fdde40da20ba6eff4f05a0b2b479dd7f428feb7e99
# derivation: linear._power_law_top
# source key: c0b268e8f55b26f011d3 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: F_0, K, n, m
# expression sha256: 1608b90f5fab4fef0955b1d13283288848aad2698d39d3b6ad3eb3bc667dd20c (of its srepr)
def _lambdifygenerated(F_0, K, n, m):
    x0 = (1/2)/n
    return 2*F_0**(1/2 - x0)*K**x0*numpy.sqrt(n)/numpy.sqrt(m)
