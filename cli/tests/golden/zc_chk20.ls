/PROG  ZC_CHK20
/ATTR
OWNER		= MNEDITOR;
COMMENT		= "zerocal";
PROG_SIZE	= 0;
CREATE		= DATE 23-11-14  TIME 22:13:20;
MODIFIED	= DATE 23-11-14  TIME 22:13:20;
FILE_NAME	= ;
VERSION		= 0;
LINE_COUNT	= 187;
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
  10:  ! 43 poses (2, 16, 17, ;
  11:  ! 19, 35), at the ;
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
  53:  ! and continue: the ;
  54:  ! program ends there ;
  55:  ! and the robot is ;
  56:  ! free. Then read the ;
  57:  ! pendant on the bench ;
  58:  ! as in stage 0 (4 ;
  59:  ! headings, turned by ;
  60:  ! hand about a quarter ;
  61:  ! turn on the same ;
  62:  ! spot between them). ;
  63:  ! Speed: joint moves ;
  64:  ! at 10 % of each ;
  65:  ! joint's maximum ;
  66:  ! speed, exact stops. ;
  67:  ! Dwell 3.1 s at each ;
  68:  ! capture: settling 1 ;
  69:  ! s (stated default) + ;
  70:  ! the pendant's 2 s ;
  71:  ! still window + 2 ;
  72:  ! sensor periods of ;
  73:  ! 0.05 s. ;
  74:  ! Predicted robot time ;
  75:  ! 3.0 min, until the ;
  76:  ! pendant is off the ;
  77:  ! flange: motion 29 s, ;
  78:  ! dwell 31 s (10 ;
  79:  ! captures), 2 ;
  80:  ! mountings 120 s, ;
  81:  ! operator OKs 0 s; ;
  82:  ! then the closing ;
  83:  ! bench readings, 42 ;
  84:  ! s, the robot free. ;
  85:  ! WARNING: the path is ;
  86:  ! NOT checked for ;
  87:  ! collisions with the ;
  88:  ! cell, the pendant or ;
  89:  ! its bracket. Check ;
  90:  ! the cell, then step ;
  91:  ! through the program ;
  92:  ! once at reduced ;
  93:  ! speed (T1) before ;
  94:  ! running it. ;
  95:  ! zerocal check: the ;
  96:  ! pendant goes on the ;
  97:  ! flange here, tilted ;
  98:  ! past its range so ;
  99:  ! that it cannot ;
 100:  ! capture yet ;
 101:J P[1] 10% FINE ;
 102:  MESSAGE[zerocal: clip the] ;
 103:  MESSAGE[pendant to the] ;
 104:  MESSAGE[flange (its screen] ;
 105:  MESSAGE[at POSE 1), then] ;
 106:  MESSAGE[continue.] ;
 107:  PAUSE ;
 108:  ! zerocal check: pose ;
 109:  ! 2 of 43, captured ;
 110:  ! from below, then ;
 111:  ! from above ;
 112:J P[2] 10% FINE ;
 113:J P[3] 10% FINE ;
 114:  WAIT   3.10(sec) ;
 115:J P[4] 10% FINE ;
 116:J P[5] 10% FINE ;
 117:  WAIT   3.10(sec) ;
 118:  ! zerocal check: pose ;
 119:  ! 16 of 43, captured ;
 120:  ! from below, then ;
 121:  ! from above ;
 122:J P[6] 10% FINE ;
 123:J P[7] 10% FINE ;
 124:  WAIT   3.10(sec) ;
 125:J P[8] 10% FINE ;
 126:J P[9] 10% FINE ;
 127:  WAIT   3.10(sec) ;
 128:  ! zerocal check: pose ;
 129:  ! 17 of 43, captured ;
 130:  ! from below, then ;
 131:  ! from above ;
 132:J P[10] 10% FINE ;
 133:J P[11] 10% FINE ;
 134:  WAIT   3.10(sec) ;
 135:J P[12] 10% FINE ;
 136:J P[13] 10% FINE ;
 137:  WAIT   3.10(sec) ;
 138:  ! zerocal check: pose ;
 139:  ! 19 of 43, captured ;
 140:  ! from below, then ;
 141:  ! from above ;
 142:J P[14] 10% FINE ;
 143:J P[15] 10% FINE ;
 144:  WAIT   3.10(sec) ;
 145:J P[16] 10% FINE ;
 146:J P[17] 10% FINE ;
 147:  WAIT   3.10(sec) ;
 148:  ! zerocal check: pose ;
 149:  ! 35 of 43, captured ;
 150:  ! from below, then ;
 151:  ! from above ;
 152:J P[18] 10% FINE ;
 153:J P[19] 10% FINE ;
 154:  WAIT   3.10(sec) ;
 155:J P[20] 10% FINE ;
 156:J P[21] 10% FINE ;
 157:  WAIT   3.10(sec) ;
 158:  ! zerocal: the check's ;
 159:  ! poses done; the ;
 160:  ! robot parks where ;
 161:  ! the pendant went on ;
 162:  ! the flange (tilted ;
 163:  ! past its range) to ;
 164:  ! take the pendant off ;
 165:J P[22] 10% FINE ;
 166:  MESSAGE[zerocal: take the] ;
 167:  MESSAGE[pendant off the] ;
 168:  MESSAGE[flange, then] ;
 169:  MESSAGE[continue: the] ;
 170:  MESSAGE[program ends and the] ;
 171:  MESSAGE[robot is free. On] ;
 172:  MESSAGE[the bench of stage] ;
 173:  MESSAGE[0, read the pendant] ;
 174:  MESSAGE[at its 4 headings as] ;
 175:  MESSAGE[it guides (the] ;
 176:  MESSAGE[closing bench] ;
 177:  MESSAGE[readings).] ;
 178:  PAUSE ;
 179:  ! zerocal: the robot's ;
 180:  ! part of the check is ;
 181:  ! done; after the ;
 182:  ! closing bench ;
 183:  ! readings, export it ;
 184:  ! from the pendant ;
 185:  ! (zerocal pendant ;
 186:  ! export), then ;
 187:  ! zerocal check ;
/POS
P[1]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -45.000 deg,	J3=    11.639 deg,
	J4=   -38.765 deg,	J5=   -64.561 deg,	J6=    38.382 deg
};
P[2]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    60.295 deg,	J3=    10.639 deg,
	J4=   -39.765 deg,	J5=   -20.561 deg,	J6=    37.382 deg
};
P[3]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    61.295 deg,	J3=    11.639 deg,
	J4=   -38.765 deg,	J5=   -19.561 deg,	J6=    38.382 deg
};
P[4]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    65.295 deg,	J3=    15.639 deg,
	J4=   -34.765 deg,	J5=   -15.561 deg,	J6=    42.382 deg
};
P[5]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    61.295 deg,	J3=    11.639 deg,
	J4=   -38.765 deg,	J5=   -19.561 deg,	J6=    38.382 deg
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
	J1=   -91.000 deg,	J2=     6.029 deg,	J3=   -37.124 deg,
	J4=   -48.051 deg,	J5=  -134.195 deg,	J6=   143.544 deg
};
P[19]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     7.029 deg,	J3=   -36.124 deg,
	J4=   -47.051 deg,	J5=  -133.195 deg,	J6=   144.544 deg
};
P[20]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    11.029 deg,	J3=   -32.124 deg,
	J4=   -43.051 deg,	J5=  -129.195 deg,	J6=   148.544 deg
};
P[21]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     7.029 deg,	J3=   -36.124 deg,
	J4=   -47.051 deg,	J5=  -133.195 deg,	J6=   144.544 deg
};
P[22]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -45.000 deg,	J3=    11.639 deg,
	J4=   -38.765 deg,	J5=   -64.561 deg,	J6=    38.382 deg
};
/END
