# The ct-skin-bone preset over the default CT's range (-1024 .. 2697 HU), opacity per millimetre,
# as a file both `adaptivert render --tf` and the ParaView tests read (scalar r g b opacity).
unit-distance 1
-1024 0    0    0    0
-600  0.75 0.45 0.3  0
-450  0.9  0.6  0.45 0.12
-300  0.9  0.65 0.5  0
200   0.95 0.85 0.7  0
450   1    0.95 0.85 0.25
1200  1    1    0.95 0.7
2697  1    1    1    0.8
