# ringchain generated code v1 sha256=19429cd09ef58d400721c5346ae208fc7252034421be3ce3087e9a6ee4a0fce9
# derivation: solitary._profile
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: x, F_m, K, n, a
# expression sha256: 374e19a6842a67d604d9485925891da307e6f760e7df9f2c482fbf51ef3fd2b7 (of its srepr)
def _lambdifygenerated(x, F_m, K, n, a):
    x0 = n - 1
    x1 = x*x0
    x2 = numpy.sqrt(6)/(a*numpy.sqrt(n)*numpy.sqrt(n + 1))
    x3 = numpy.less(x2*abs(x1), (1/2)*numpy.pi)
    return numpy.select([x3,True], [F_m*numpy.exp(2*n*numpy.log(numpy.cos(numpy.select([x3,True], [x1*x2,0], default=numpy.nan)))/x0),0], default=numpy.nan)
