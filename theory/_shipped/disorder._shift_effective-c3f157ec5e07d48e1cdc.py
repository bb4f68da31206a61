# ringchain generated code v1 sha256=f3c6ec0124bf8a8f00cadd334723f25d078059fa4d3391f347bd65a46fc294f5
# derivation: disorder._shift_effective
# source key: caeff341571871d5b69b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: n, sigma_K
# expression sha256: b99b6abffce9e43fc0324d23919c27a872f3a7d40754cde6675f9b665396ea9a (of its srepr)
def _lambdifygenerated(n, sigma_K):
    x0 = (1/4)*sigma_K**2
    return -x0/n - x0/n**2
