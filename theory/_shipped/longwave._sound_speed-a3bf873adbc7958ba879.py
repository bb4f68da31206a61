# ringchain generated code v1 sha256=d0e19bce25de6a0a8b275a3802d7e8e15d7b0ece34b94065f99856ce02d50cb7
# derivation: longwave._sound_speed
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: K, n, a, m
# expression sha256: 9f76c9b52a089bf8df7fa7a1b6f8bd88fa49a927608a98968eb7685fdc7cedb2 (of its srepr)
def _lambdifygenerated(K, n, a, m):
    x0 = (1/2)/n
    return (x0*numpy.log(K) + numpy.log(a) - 1/2*numpy.log(m) + (1/2)*numpy.log(n), x0*(n - 1),)
