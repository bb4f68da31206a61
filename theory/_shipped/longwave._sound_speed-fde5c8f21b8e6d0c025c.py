# ringchain generated code v1 sha256=4112058f341b573787ebce7c1708b905dd763e9a493540d17b5270486efc8414
# derivation: longwave._sound_speed
# source key: 263ab3517922b3fc21eb (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: K, n, a, m
# expression sha256: 9f76c9b52a089bf8df7fa7a1b6f8bd88fa49a927608a98968eb7685fdc7cedb2 (of its srepr)
def _lambdifygenerated(K, n, a, m):
    x0 = (1/2)/n
    return (x0*numpy.log(K) + numpy.log(a) - 1/2*numpy.log(m) + (1/2)*numpy.log(n), x0*(n - 1),)
