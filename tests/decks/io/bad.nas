BEGIN BULK
GRID           1       0      0.      0.      0.
CTRIA3         1       1       1       2  oops
ENDDATA
