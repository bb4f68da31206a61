# ringchain generated code v1 sha256=8c498f1c6cd9f95857fff64b85c44e9471e4fbcca8bb234b9b266c30e4eb0caf
# derivation: disorder._shift_effective
# source key: c0b268e8f55b26f011d3 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: n, sigma_K
# expression sha256: b99b6abffce9e43fc0324d23919c27a872f3a7d40754cde6675f9b665396ea9a (of its srepr)
def _lambdifygenerated(n, sigma_K):
    x0 = (1/4)*sigma_K**2
    return -x0/n - x0/n**2
