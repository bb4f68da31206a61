# ringchain generated code v1 sha256=1e45c0df2723836cad151e6f10a8ceb23029e45390e716c653a7fa00fcc317f9
# derivation: linear._impact_speed
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: h, g
# expression sha256: 78e19f22b1980e24ec3dd4fe4cae41965662f526eed175e5eee688ad141fb7c8 (of its srepr)
def _lambdifygenerated(h, g):
    return numpy.sqrt(2)*numpy.sqrt(g)*numpy.sqrt(h)
