# ringchain generated code v1 sha256=39fa7c2f9e684d8cbc5cdeb2f230bd5a23f559b475c2b425f1063103ce1eac25
# derivation: disorder._shift_effective
# source key: 10a35615fa68ecdff34f (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: n, sigma_K
# expression sha256: b99b6abffce9e43fc0324d23919c27a872f3a7d40754cde6675f9b665396ea9a (of its srepr)
def _lambdifygenerated(n, sigma_K):
    x0 = (1/4)*sigma_K**2
    return -x0/n - x0/n**2
