# ringchain generated code v1 sha256=b1c714f8f0ebfc4af87f5a2d608f819684c7f8e5a4018772238d18ae580c2199
# derivation: disorder._shift_effective
# source key: 263ab3517922b3fc21eb (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: n, sigma_K
# expression sha256: b99b6abffce9e43fc0324d23919c27a872f3a7d40754cde6675f9b665396ea9a (of its srepr)
def _lambdifygenerated(n, sigma_K):
    x0 = (1/4)*sigma_K**2
    return -x0/n - x0/n**2
