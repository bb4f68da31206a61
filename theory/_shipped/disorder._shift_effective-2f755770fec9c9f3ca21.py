# ringchain generated code v1 sha256=c7ba1d13f43a4571278eee85ee0a0ed03072d45dd958f21b02081effcaf122dd
# derivation: disorder._shift_effective
# source key: 0d3b9b67499038ff2889 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: n, sigma_K
# expression sha256: b99b6abffce9e43fc0324d23919c27a872f3a7d40754cde6675f9b665396ea9a (of its srepr)
def _lambdifygenerated(n, sigma_K):
    x0 = (1/4)*sigma_K**2
    return -x0/n - x0/n**2
