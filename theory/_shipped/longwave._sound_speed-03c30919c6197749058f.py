# ringchain generated code v1 sha256=a576d5e903fcad750c1ef91cf455ffba85d63b60685cb43d4253fd16becd8250
# derivation: longwave._sound_speed
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: K, n, a, m
# expression sha256: 9f76c9b52a089bf8df7fa7a1b6f8bd88fa49a927608a98968eb7685fdc7cedb2 (of its srepr)
def _lambdifygenerated(K, n, a, m):
    x0 = (1/2)/n
    return (x0*numpy.log(K) + numpy.log(a) - 1/2*numpy.log(m) + (1/2)*numpy.log(n), x0*(n - 1),)
