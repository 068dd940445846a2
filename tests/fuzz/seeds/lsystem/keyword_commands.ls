recursion 3
angle 60
thickness 8
poly_limit 50
axiom [F]"(0.8)[&F]%Z!(2)g
rule F = F[>(10)$F]z;(1):?_
