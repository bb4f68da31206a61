# ringchain generated code v1 sha256=c764fed7361b8da4c8102515d51e134c6e29642ade01122f4736406a333c7364
# derivation: rigid._modulus_pair
# source key: 0881d513a06819d2e367 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: E_1, nu_1, E_2, nu_2
# expression sha256: 048c9cabb01bda9f3cab2a722b38eb0c89f51ffe1d090e7feeb1e997fdf02c9a (of its srepr)
def _lambdifygenerated(E_1, nu_1, E_2, nu_2):
    return -E_1*E_2/(E_1*nu_2**2 - E_1 + E_2*nu_1**2 - E_2)
