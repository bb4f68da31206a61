# ringchain generated code v1 sha256=c36363e3244378d86539584a182eca10cdf2c3df805ad3eae6a469862aa701ff
# derivation: linear._impact_speed
# source key: 317867d47b5755454417 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: h, g
# expression sha256: 78e19f22b1980e24ec3dd4fe4cae41965662f526eed175e5eee688ad141fb7c8 (of its srepr)
def _lambdifygenerated(h, g):
    return numpy.sqrt(2)*numpy.sqrt(g)*numpy.sqrt(h)
