# ringchain generated code v1 sha256=75901fc1df6ce99228a96d1877df995455c32ea9872f8e90bfcbf1c2cf338212
# derivation: solitary._width
# source key: 317867d47b5755454417 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: n, a
# expression sha256: 4aa027b2f755104129bd07b7bcca6290607a7f917e9760a259dd9fdceb4098a1 (of its srepr)
def _lambdifygenerated(n, a):
    return (1/6)*numpy.sqrt(6)*numpy.pi*a*numpy.sqrt(n)*numpy.sqrt(n + 1)/(n - 1)
