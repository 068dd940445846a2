# a branching bush, numeric dialect
5
22.5
12
c(3)A
A=F[&+A][&-A][^(30)A]FA
F=FF
@
