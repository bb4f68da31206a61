# ringchain generated code v1 sha256=e008dd399be4316cac809741e8fb86b85a8f2a5c5684d047be8f55a32791c2a5
# derivation: rigid._modulus_pair
# source key: caeff341571871d5b69b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: E_1, nu_1, E_2, nu_2
# expression sha256: 048c9cabb01bda9f3cab2a722b38eb0c89f51ffe1d090e7feeb1e997fdf02c9a (of its srepr)
def _lambdifygenerated(E_1, nu_1, E_2, nu_2):
    return -E_1*E_2/(E_1*nu_2**2 - E_1 + E_2*nu_1**2 - E_2)
