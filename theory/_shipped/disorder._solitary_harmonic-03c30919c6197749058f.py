# ringchain generated code v1 sha256=f325149e184abe86a94645dbbd28a750257308419fef35ace0d1d5f1e6214a7f
# derivation: disorder._solitary_harmonic
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: n, log_F_m, log_mean_a, log_mean_ray
# expression sha256: b1944c48b42875142772c5a2f1e11fb3993471ae0ea63112b80593632d9ff7fc (of its srepr)
def _lambdifygenerated(n, log_F_m, log_mean_a, log_mean_ray):
    x0 = (1/2)*log_F_m
    return log_mean_a - log_mean_ray + x0 - 1/2*numpy.log(n + 1) + (1/2)*numpy.log(2) - x0/n
