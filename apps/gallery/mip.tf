# A grey ramp at full opacity, for maximum-intensity projection of CT (scalar r g b opacity).
-1024 0 0 0 1
-200  0.05 0.05 0.05 1
1500  1 1 1 1
