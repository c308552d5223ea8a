/PROG  FUZZ_SEED
/ATTR
OWNER		= MNEDITOR;
COMMENT		= "";
LINE_COUNT	= 3;
DEFAULT_GROUP	= 1,*,*,*,*;
/MN
	1:  UFRAME_NUM=0 ;
	2:J P[1] 100% CNT60 	;
	3:L P[2] 200mm/sec CNT60 	;
/POS
P[1]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =	653.350855	mm,	Y =	600.959864	mm,	Z =	660.701574	mm,
	W =	4.261677	deg,	P =	13.559316	deg,	R =	12.082948	deg
};
P[2]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =	669.002648	mm,	Y =	558.748509	mm,	Z =	847.687800	mm,
	W =	12.096094	deg,	P =	19.311778	deg,	R =	14.653627	deg
};
/END
