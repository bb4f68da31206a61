# ringchain generated code v1 sha256=1bea34672a51b07f18429ae36afd1f680e8bea21d643a7fd064aec4468512f32
# derivation: disorder._shift_effective
# source key: aaa6be78b00d30412b2b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: n, sigma_K
# expression sha256: b99b6abffce9e43fc0324d23919c27a872f3a7d40754cde6675f9b665396ea9a (of its srepr)
def _lambdifygenerated(n, sigma_K):
    x0 = (1/4)*sigma_K**2
    return -x0/n - x0/n**2
