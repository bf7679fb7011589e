/PROG  ZC_CHK20
/ATTR
OWNER		= MNEDITOR;
COMMENT		= "zerocal";
PROG_SIZE	= 0;
CREATE		= DATE 23-11-14  TIME 22:13:20;
MODIFIED	= DATE 23-11-14  TIME 22:13:20;
FILE_NAME	= ;
VERSION		= 0;
LINE_COUNT	= 179;
MEMORY_SIZE	= 0;
PROTECT		= READ_WRITE;
TCD:  STACK_SIZE	= 0,
      TASK_PRIORITY	= 50,
      TIME_SLICE	= 0,
      BUSY_LAMP_OFF	= 0,
      ABORT_REQUEST	= 0,
      PAUSE_REQUEST	= 0;
DEFAULT_GROUP	= 1,*,*,*,*;
CONTROL_CODE	= 00000000 00000000;
/MN
   1:  ! zerocal robot ;
   2:  ! program: a check of ;
   3:  ! the offsets entered ;
   4:  ! after a calibration ;
   5:  ! session. ;
   6:  ! Robot FANUC M-20iA ;
   7:  ! (profile ;
   8:  ! fanuc-m20ia); 5 of ;
   9:  ! the session plan's ;
  10:  ! 43 poses (28, 30, ;
  11:  ! 31, 33, 34), at the ;
  12:  ! session's commanded ;
  13:  ! angles. Written by ;
  14:  ! zerocal 0.1.0. ;
  15:  ! Every pose is ;
  16:  ! captured twice: ;
  17:  ! first with every ;
  18:  ! joint arriving ;
  19:  ! moving positive ;
  20:  ! (from 1 deg below), ;
  21:  ! then, after every ;
  22:  ! joint has gone 4 deg ;
  23:  ! past it, moving ;
  24:  ! negative (from ;
  25:  ! above). The pendant ;
  26:  ! averages the two: ;
  27:  ! the middle of every ;
  28:  ! gear's backlash. ;
  29:  ! Before it: stage 0 ;
  30:  ! on the bench (the ;
  31:  ! pendant's check mode ;
  32:  ! starts there). Stop: ;
  33:  ! clip the pendant to ;
  34:  ! the flange (the ;
  35:  ! robot stands with ;
  36:  ! the pendant tilted ;
  37:  ! past its range, so ;
  38:  ! it cannot capture ;
  39:  ! early). Then the ;
  40:  ! check's poses in the ;
  41:  ! plan's order, twice ;
  42:  ! each; the pendant ;
  43:  ! must hold the same ;
  44:  ! plan as the session ;
  45:  ! (plan set). No stage ;
  46:  ! 1. ;
  47:  ! Closing bench ;
  48:  ! readings: the robot ;
  49:  ! parks where the ;
  50:  ! pendant went on the ;
  51:  ! flange and stops; ;
  52:  ! take the pendant off ;
  53:  ! and read it on the ;
  54:  ! bench as in stage 0 ;
  55:  ! (4 headings, turned ;
  56:  ! by hand about a ;
  57:  ! quarter turn on the ;
  58:  ! same spot between ;
  59:  ! them). The program ;
  60:  ! ends there. ;
  61:  ! Speed: joint moves ;
  62:  ! at 10 % of each ;
  63:  ! joint's maximum ;
  64:  ! speed, exact stops. ;
  65:  ! Dwell 3.1 s at each ;
  66:  ! capture: settling 1 ;
  67:  ! s (stated default) + ;
  68:  ! the pendant's 2 s ;
  69:  ! still window + 2 ;
  70:  ! sensor periods of ;
  71:  ! 0.05 s. ;
  72:  ! Predicted robot time ;
  73:  ! 3.7 min, the closing ;
  74:  ! bench readings ;
  75:  ! included: motion 26 ;
  76:  ! s, dwell 43 s (14 ;
  77:  ! captures), 2 ;
  78:  ! mountings 120 s, ;
  79:  ! operator OKs 30 s. ;
  80:  ! WARNING: the path is ;
  81:  ! NOT checked for ;
  82:  ! collisions with the ;
  83:  ! cell, the pendant or ;
  84:  ! its bracket. Check ;
  85:  ! the cell, then step ;
  86:  ! through the program ;
  87:  ! once at reduced ;
  88:  ! speed (T1) before ;
  89:  ! running it. ;
  90:  ! zerocal check: the ;
  91:  ! pendant goes on the ;
  92:  ! flange here, tilted ;
  93:  ! past its range so ;
  94:  ! that it cannot ;
  95:  ! capture yet ;
  96:J P[1] 10% FINE ;
  97:  MESSAGE[zerocal: clip the] ;
  98:  MESSAGE[pendant to the] ;
  99:  MESSAGE[flange (its screen] ;
 100:  MESSAGE[at POSE 1), then] ;
 101:  MESSAGE[continue.] ;
 102:  PAUSE ;
 103:  ! zerocal check: pose ;
 104:  ! 28 of 43, captured ;
 105:  ! from below, then ;
 106:  ! from above ;
 107:J P[2] 10% FINE ;
 108:J P[3] 10% FINE ;
 109:  WAIT   3.10(sec) ;
 110:J P[4] 10% FINE ;
 111:J P[5] 10% FINE ;
 112:  WAIT   3.10(sec) ;
 113:  ! zerocal check: pose ;
 114:  ! 30 of 43, captured ;
 115:  ! from below, then ;
 116:  ! from above ;
 117:J P[6] 10% FINE ;
 118:J P[7] 10% FINE ;
 119:  WAIT   3.10(sec) ;
 120:J P[8] 10% FINE ;
 121:J P[9] 10% FINE ;
 122:  WAIT   3.10(sec) ;
 123:  ! zerocal check: pose ;
 124:  ! 31 of 43, captured ;
 125:  ! from below, then ;
 126:  ! from above ;
 127:J P[10] 10% FINE ;
 128:J P[11] 10% FINE ;
 129:  WAIT   3.10(sec) ;
 130:J P[12] 10% FINE ;
 131:J P[13] 10% FINE ;
 132:  WAIT   3.10(sec) ;
 133:  ! zerocal check: pose ;
 134:  ! 33 of 43, captured ;
 135:  ! from below, then ;
 136:  ! from above ;
 137:J P[14] 10% FINE ;
 138:J P[15] 10% FINE ;
 139:  WAIT   3.10(sec) ;
 140:J P[16] 10% FINE ;
 141:J P[17] 10% FINE ;
 142:  WAIT   3.10(sec) ;
 143:  ! zerocal check: pose ;
 144:  ! 34 of 43, captured ;
 145:  ! from below, then ;
 146:  ! from above ;
 147:J P[18] 10% FINE ;
 148:J P[19] 10% FINE ;
 149:  WAIT   3.10(sec) ;
 150:J P[20] 10% FINE ;
 151:J P[21] 10% FINE ;
 152:  WAIT   3.10(sec) ;
 153:  ! zerocal: the check's ;
 154:  ! poses done; the ;
 155:  ! robot parks where ;
 156:  ! the pendant went on ;
 157:  ! the flange (tilted ;
 158:  ! past its range) for ;
 159:  ! the closing bench ;
 160:  ! readings ;
 161:J P[22] 10% FINE ;
 162:  MESSAGE[zerocal: closing] ;
 163:  MESSAGE[bench readings: take] ;
 164:  MESSAGE[the pendant off the] ;
 165:  MESSAGE[flange to the bench] ;
 166:  MESSAGE[of stage 0 and read] ;
 167:  MESSAGE[it at 4 headings,] ;
 168:  MESSAGE[turned by hand about] ;
 169:  MESSAGE[a quarter turn on] ;
 170:  MESSAGE[the same spot] ;
 171:  MESSAGE[between them, as the] ;
 172:  MESSAGE[pendant guides. Then] ;
 173:  MESSAGE[continue.] ;
 174:  PAUSE ;
 175:  ! zerocal: check done; ;
 176:  ! export it from the ;
 177:  ! pendant (zerocal ;
 178:  ! pendant export), ;
 179:  ! then zerocal check ;
/POS
P[1]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -45.000 deg,	J3=   -36.124 deg,
	J4=   -47.051 deg,	J5=   -88.195 deg,	J6=   144.544 deg
};
P[2]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=     6.029 deg,	J3=   -37.124 deg,
	J4=   -48.051 deg,	J5=  -134.195 deg,	J6=   143.544 deg
};
P[3]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     7.029 deg,	J3=   -36.124 deg,
	J4=   -47.051 deg,	J5=  -133.195 deg,	J6=   144.544 deg
};
P[4]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    11.029 deg,	J3=   -32.124 deg,
	J4=   -43.051 deg,	J5=  -129.195 deg,	J6=   148.544 deg
};
P[5]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     7.029 deg,	J3=   -36.124 deg,
	J4=   -47.051 deg,	J5=  -133.195 deg,	J6=   144.544 deg
};
P[6]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    34.809 deg,	J3=   -14.886 deg,
	J4=  -142.416 deg,	J5=   -17.126 deg,	J6=   135.967 deg
};
P[7]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    35.809 deg,	J3=   -13.886 deg,
	J4=  -141.416 deg,	J5=   -16.126 deg,	J6=   136.967 deg
};
P[8]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    39.809 deg,	J3=    -9.886 deg,
	J4=  -137.416 deg,	J5=   -12.126 deg,	J6=   140.967 deg
};
P[9]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    35.809 deg,	J3=   -13.886 deg,
	J4=  -141.416 deg,	J5=   -16.126 deg,	J6=   136.967 deg
};
P[10]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    61.880 deg,	J3=    17.074 deg,
	J4=  -172.242 deg,	J5=    21.746 deg,	J6=   175.793 deg
};
P[11]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    62.880 deg,	J3=    18.074 deg,
	J4=  -171.242 deg,	J5=    22.746 deg,	J6=   176.793 deg
};
P[12]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    66.880 deg,	J3=    22.074 deg,
	J4=  -167.242 deg,	J5=    26.746 deg,	J6=   180.793 deg
};
P[13]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    62.880 deg,	J3=    18.074 deg,
	J4=  -171.242 deg,	J5=    22.746 deg,	J6=   176.793 deg
};
P[14]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    73.671 deg,	J3=    14.236 deg,
	J4=   -42.633 deg,	J5=   -23.520 deg,	J6=    38.517 deg
};
P[15]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    74.671 deg,	J3=    15.236 deg,
	J4=   -41.633 deg,	J5=   -22.520 deg,	J6=    39.517 deg
};
P[16]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    78.671 deg,	J3=    19.236 deg,
	J4=   -37.633 deg,	J5=   -18.520 deg,	J6=    43.517 deg
};
P[17]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    74.671 deg,	J3=    15.236 deg,
	J4=   -41.633 deg,	J5=   -22.520 deg,	J6=    39.517 deg
};
P[18]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    60.295 deg,	J3=    10.639 deg,
	J4=   -39.765 deg,	J5=   -20.561 deg,	J6=    37.382 deg
};
P[19]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    61.295 deg,	J3=    11.639 deg,
	J4=   -38.765 deg,	J5=   -19.561 deg,	J6=    38.382 deg
};
P[20]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    65.295 deg,	J3=    15.639 deg,
	J4=   -34.765 deg,	J5=   -15.561 deg,	J6=    42.382 deg
};
P[21]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    61.295 deg,	J3=    11.639 deg,
	J4=   -38.765 deg,	J5=   -19.561 deg,	J6=    38.382 deg
};
P[22]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -45.000 deg,	J3=   -36.124 deg,
	J4=   -47.051 deg,	J5=   -88.195 deg,	J6=   144.544 deg
};
/END
