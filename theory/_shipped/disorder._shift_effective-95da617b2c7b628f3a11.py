# ringchain generated code v1 sha256=d78e94c194c2179a819988066b962dea57c940b967db332746897360a08fb2db
# derivation: disorder._shift_effective
# source key: f3be020559998432f519 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: n, sigma_K
# expression sha256: b99b6abffce9e43fc0324d23919c27a872f3a7d40754cde6675f9b665396ea9a (of its srepr)
def _lambdifygenerated(n, sigma_K):
    x0 = (1/4)*sigma_K**2
    return -x0/n - x0/n**2
