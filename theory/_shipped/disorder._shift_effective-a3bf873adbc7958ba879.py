# ringchain generated code v1 sha256=c221a0534c66138f37ed719762c3eae7a96252170e6c9d3a6fd1a649be25878c
# derivation: disorder._shift_effective
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: n, sigma_K
# expression sha256: b99b6abffce9e43fc0324d23919c27a872f3a7d40754cde6675f9b665396ea9a (of its srepr)
def _lambdifygenerated(n, sigma_K):
    x0 = (1/4)*sigma_K**2
    return -x0/n - x0/n**2
