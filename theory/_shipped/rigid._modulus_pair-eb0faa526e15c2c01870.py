# ringchain generated code v1 sha256=f80047f8923ad6c6974e6ac212102ce27c9c8d129c8fb3a485aa3a9cc0617a5e
# derivation: rigid._modulus_pair
# source key: c0b268e8f55b26f011d3 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: E_1, nu_1, E_2, nu_2
# expression sha256: 048c9cabb01bda9f3cab2a722b38eb0c89f51ffe1d090e7feeb1e997fdf02c9a (of its srepr)
def _lambdifygenerated(E_1, nu_1, E_2, nu_2):
    return -E_1*E_2/(E_1*nu_2**2 - E_1 + E_2*nu_1**2 - E_2)
