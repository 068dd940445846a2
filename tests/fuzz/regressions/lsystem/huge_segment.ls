# A segment of 1e308 units beside ordinary ones: the silhouette box count must not convert
# an overflowed coordinate to an integer.
3
30
10
X
X=F(1e308)[+F]F
@
