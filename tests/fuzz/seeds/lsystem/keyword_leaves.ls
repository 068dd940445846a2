# leaves, tropism and random turns, keyword dialect
recursion 4
angle 30
thickness 20
min_thickness 4
shape 0
color 3 90 140 40
axiom c(2)T
rule T = F t(0.2) [+L] [-L] ~(15) T
rule L = c3 {.-f.+f.+f.-|-f.+f.+f}
