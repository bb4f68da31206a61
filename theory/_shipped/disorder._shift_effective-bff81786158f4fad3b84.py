# ringchain generated code v1 sha256=430cff34f048c5a15b0b6ce1d056a78e9fb961ddaaa48794fcc6749209cc3a5b
# derivation: disorder._shift_effective
# source key: 07201ab9dccdbac32795 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: n, sigma_K
# expression sha256: b99b6abffce9e43fc0324d23919c27a872f3a7d40754cde6675f9b665396ea9a (of its srepr)
def _lambdifygenerated(n, sigma_K):
    x0 = (1/4)*sigma_K**2
    return -x0/n - x0/n**2
