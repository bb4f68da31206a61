# ringchain generated code v1 sha256=f1e71c800964d86def3ae12af8cc69e764ae9cdcfee17ff8a014c5de49f03718
# derivation: disorder._shift_effective
# source key: 317867d47b5755454417 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: n, sigma_K
# expression sha256: b99b6abffce9e43fc0324d23919c27a872f3a7d40754cde6675f9b665396ea9a (of its srepr)
def _lambdifygenerated(n, sigma_K):
    x0 = (1/4)*sigma_K**2
    return -x0/n - x0/n**2
