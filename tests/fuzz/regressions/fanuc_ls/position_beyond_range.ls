/PROG  A
/MN
   1:L P[1] 100mm/sec FINE ;
/POS
P[1]{
   GP1:
	UF : 0, UT : 1,
	X = 1e300 mm, Y = 2 mm, Z = 3 mm,
	W = 0 deg, P = 0 deg, R = 0 deg
};
/END
