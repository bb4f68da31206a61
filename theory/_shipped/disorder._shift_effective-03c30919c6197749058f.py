# ringchain generated code v1 sha256=956d2aeabcb3ad9a1d33cc71d5ca2ffc301293f8a9d9fbf9936b6d9f0197144f
# derivation: disorder._shift_effective
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: n, sigma_K
# expression sha256: b99b6abffce9e43fc0324d23919c27a872f3a7d40754cde6675f9b665396ea9a (of its srepr)
def _lambdifygenerated(n, sigma_K):
    x0 = (1/4)*sigma_K**2
    return -x0/n - x0/n**2
