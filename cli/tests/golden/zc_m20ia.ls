/PROG  ZC_M20IA
/ATTR
OWNER		= MNEDITOR;
COMMENT		= "zerocal";
PROG_SIZE	= 0;
CREATE		= DATE 23-11-14  TIME 22:13:20;
MODIFIED	= DATE 23-11-14  TIME 22:13:20;
FILE_NAME	= ;
VERSION		= 0;
LINE_COUNT	= 224;
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
   2:  ! program: a ;
   3:  ! joint-zero ;
   4:  ! calibration session. ;
   5:  ! Robot FANUC M-20iA ;
   6:  ! (profile ;
   7:  ! fanuc-m20ia); 24 ;
   8:  ! stage-2 poses. ;
   9:  ! Written by zerocal ;
  10:  ! 0.1.0; targets in ;
  11:  ! the controller's ;
  12:  ! joint degrees. ;
  13:  ! Stop: clip the ;
  14:  ! pendant to the upper ;
  15:  ! arm (the robot ;
  16:  ! stands with the ;
  17:  ! pendant tilted past ;
  18:  ! its range, so it ;
  19:  ! cannot capture ;
  20:  ! early). Stage 1: the ;
  21:  ! stage-1 pose, then ;
  22:  ! joint 1 turned by ;
  23:  ! 180 deg (an OK on ;
  24:  ! the pendant takes ;
  25:  ! that reading). Stop: ;
  26:  ! joint 1 back, clip ;
  27:  ! the pendant to the ;
  28:  ! flange (tilted ;
  29:  ! again). Stage 2: the ;
  30:  ! plan's poses in its ;
  31:  ! order; load the same ;
  32:  ! plan into the ;
  33:  ! pendant (plan set). ;
  34:  ! Speed: joint moves ;
  35:  ! at 10 % of each ;
  36:  ! joint's maximum ;
  37:  ! speed, exact stops. ;
  38:  ! Backlash: every ;
  39:  ! target is reached ;
  40:  ! with each joint ;
  41:  ! moving J1+ J2+ J3+ ;
  42:  ! J4+ J5- J6+. ;
  43:  ! Dwell 3.1 s at each ;
  44:  ! capture: settling 1 ;
  45:  ! s (stated default) + ;
  46:  ! the pendant's 2 s ;
  47:  ! still window + 2 ;
  48:  ! sensor periods. ;
  49:  ! Predicted robot time ;
  50:  ! 5.7 min (motion 131 ;
  51:  ! s, dwell 81 s, ;
  52:  ! remount 120 s, ;
  53:  ! operator OKs 10 s). ;
  54:  ! WARNING: the path is ;
  55:  ! NOT checked for ;
  56:  ! collisions with the ;
  57:  ! cell, the pendant or ;
  58:  ! its bracket. Check ;
  59:  ! the cell, then step ;
  60:  ! through the program ;
  61:  ! once at reduced ;
  62:  ! speed (T1) before ;
  63:  ! running it. ;
  64:  ! zerocal stage 1: the ;
  65:  ! pendant goes on the ;
  66:  ! upper arm here, ;
  67:  ! tilted past its ;
  68:  ! range so that it ;
  69:  ! cannot capture yet ;
  70:J P[1] 10% FINE ;
  71:J P[2] 10% FINE ;
  72:  MESSAGE[zerocal: clip the] ;
  73:  MESSAGE[pendant to the upper] ;
  74:  MESSAGE[arm (its screen at] ;
  75:  MESSAGE[STAGE 1), then] ;
  76:  MESSAGE[continue.] ;
  77:  PAUSE ;
  78:J P[3] 10% FINE ;
  79:  WAIT   3.10(sec) ;
  80:  ! zerocal stage 1: ;
  81:  ! joint 1 turned by ;
  82:  ! 180 deg ;
  83:J P[4] 10% FINE ;
  84:  WAIT   3.10(sec) ;
  85:  MESSAGE[zerocal: press OK on] ;
  86:  MESSAGE[the pendant, wait] ;
  87:  MESSAGE[for its POSE screen,] ;
  88:  MESSAGE[then continue.] ;
  89:  PAUSE ;
  90:  ! zerocal: joint 1 ;
  91:  ! back; the pendant ;
  92:  ! goes on the flange ;
  93:  ! here, tilted past ;
  94:  ! its range ;
  95:J P[5] 10% FINE ;
  96:J P[6] 10% FINE ;
  97:  MESSAGE[zerocal: clip the] ;
  98:  MESSAGE[pendant to the] ;
  99:  MESSAGE[flange (its screen] ;
 100:  MESSAGE[at POSE 1), then] ;
 101:  MESSAGE[continue.] ;
 102:  PAUSE ;
 103:  ! zerocal stage 2: ;
 104:  ! pose 1 of 24 ;
 105:J P[7] 10% FINE ;
 106:J P[8] 10% FINE ;
 107:  WAIT   3.10(sec) ;
 108:  ! zerocal stage 2: ;
 109:  ! pose 2 of 24 ;
 110:J P[9] 10% FINE ;
 111:  WAIT   3.10(sec) ;
 112:  ! zerocal stage 2: ;
 113:  ! pose 3 of 24 ;
 114:J P[10] 10% FINE ;
 115:J P[11] 10% FINE ;
 116:  WAIT   3.10(sec) ;
 117:  ! zerocal stage 2: ;
 118:  ! pose 4 of 24 ;
 119:J P[12] 10% FINE ;
 120:J P[13] 10% FINE ;
 121:  WAIT   3.10(sec) ;
 122:  ! zerocal stage 2: ;
 123:  ! pose 5 of 24 ;
 124:J P[14] 10% FINE ;
 125:J P[15] 10% FINE ;
 126:  WAIT   3.10(sec) ;
 127:  ! zerocal stage 2: ;
 128:  ! pose 6 of 24 ;
 129:J P[16] 10% FINE ;
 130:J P[17] 10% FINE ;
 131:  WAIT   3.10(sec) ;
 132:  ! zerocal stage 2: ;
 133:  ! pose 7 of 24 ;
 134:J P[18] 10% FINE ;
 135:J P[19] 10% FINE ;
 136:  WAIT   3.10(sec) ;
 137:  ! zerocal stage 2: ;
 138:  ! pose 8 of 24 ;
 139:J P[20] 10% FINE ;
 140:J P[21] 10% FINE ;
 141:  WAIT   3.10(sec) ;
 142:  ! zerocal stage 2: ;
 143:  ! pose 9 of 24 ;
 144:J P[22] 10% FINE ;
 145:J P[23] 10% FINE ;
 146:  WAIT   3.10(sec) ;
 147:  ! zerocal stage 2: ;
 148:  ! pose 10 of 24 ;
 149:J P[24] 10% FINE ;
 150:J P[25] 10% FINE ;
 151:  WAIT   3.10(sec) ;
 152:  ! zerocal stage 2: ;
 153:  ! pose 11 of 24 ;
 154:J P[26] 10% FINE ;
 155:J P[27] 10% FINE ;
 156:  WAIT   3.10(sec) ;
 157:  ! zerocal stage 2: ;
 158:  ! pose 12 of 24 ;
 159:J P[28] 10% FINE ;
 160:J P[29] 10% FINE ;
 161:  WAIT   3.10(sec) ;
 162:  ! zerocal stage 2: ;
 163:  ! pose 13 of 24 ;
 164:J P[30] 10% FINE ;
 165:J P[31] 10% FINE ;
 166:  WAIT   3.10(sec) ;
 167:  ! zerocal stage 2: ;
 168:  ! pose 14 of 24 ;
 169:J P[32] 10% FINE ;
 170:J P[33] 10% FINE ;
 171:  WAIT   3.10(sec) ;
 172:  ! zerocal stage 2: ;
 173:  ! pose 15 of 24 ;
 174:J P[34] 10% FINE ;
 175:J P[35] 10% FINE ;
 176:  WAIT   3.10(sec) ;
 177:  ! zerocal stage 2: ;
 178:  ! pose 16 of 24 ;
 179:J P[36] 10% FINE ;
 180:J P[37] 10% FINE ;
 181:  WAIT   3.10(sec) ;
 182:  ! zerocal stage 2: ;
 183:  ! pose 17 of 24 ;
 184:J P[38] 10% FINE ;
 185:J P[39] 10% FINE ;
 186:  WAIT   3.10(sec) ;
 187:  ! zerocal stage 2: ;
 188:  ! pose 18 of 24 ;
 189:J P[40] 10% FINE ;
 190:J P[41] 10% FINE ;
 191:  WAIT   3.10(sec) ;
 192:  ! zerocal stage 2: ;
 193:  ! pose 19 of 24 ;
 194:J P[42] 10% FINE ;
 195:J P[43] 10% FINE ;
 196:  WAIT   3.10(sec) ;
 197:  ! zerocal stage 2: ;
 198:  ! pose 20 of 24 ;
 199:J P[44] 10% FINE ;
 200:J P[45] 10% FINE ;
 201:  WAIT   3.10(sec) ;
 202:  ! zerocal stage 2: ;
 203:  ! pose 21 of 24 ;
 204:J P[46] 10% FINE ;
 205:J P[47] 10% FINE ;
 206:  WAIT   3.10(sec) ;
 207:  ! zerocal stage 2: ;
 208:  ! pose 22 of 24 ;
 209:J P[48] 10% FINE ;
 210:J P[49] 10% FINE ;
 211:  WAIT   3.10(sec) ;
 212:  ! zerocal stage 2: ;
 213:  ! pose 23 of 24 ;
 214:J P[50] 10% FINE ;
 215:J P[51] 10% FINE ;
 216:  WAIT   3.10(sec) ;
 217:  ! zerocal stage 2: ;
 218:  ! pose 24 of 24 ;
 219:J P[52] 10% FINE ;
 220:J P[53] 10% FINE ;
 221:  WAIT   3.10(sec) ;
 222:  ! zerocal: session ;
 223:  ! done; the pendant ;
 224:  ! shows the result ;
/POS
P[1]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -46.000 deg,	J3=    72.330 deg,
	J4=    -1.000 deg,	J5=     1.000 deg,	J6=    -1.000 deg
};
P[2]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -45.000 deg,	J3=    73.330 deg,
	J4=     0.000 deg,	J5=     0.000 deg,	J6=     0.000 deg
};
P[3]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    73.330 deg,
	J4=     0.000 deg,	J5=     0.000 deg,	J6=     0.000 deg
};
P[4]{
   GP1:
	UF : 0, UT : 0,	
	J1=    90.000 deg,	J2=     0.000 deg,	J3=    73.330 deg,
	J4=     0.000 deg,	J5=     0.000 deg,	J6=     0.000 deg
};
P[5]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=     0.000 deg,	J3=   140.118 deg,
	J4=  -193.099 deg,	J5=    90.410 deg,	J6=  -188.186 deg
};
P[6]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   140.118 deg,
	J4=  -192.099 deg,	J5=    89.410 deg,	J6=  -187.186 deg
};
P[7]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   140.118 deg,
	J4=  -192.099 deg,	J5=   135.410 deg,	J6=  -187.186 deg
};
P[8]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   140.118 deg,
	J4=  -192.099 deg,	J5=   134.410 deg,	J6=  -187.186 deg
};
P[9]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   230.255 deg,
	J4=    41.768 deg,	J5=   121.553 deg,	J6=    22.479 deg
};
P[10]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   158.772 deg,
	J4=   164.314 deg,	J5=   -19.132 deg,	J6=    12.494 deg
};
P[11]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   159.772 deg,
	J4=   164.314 deg,	J5=   -19.132 deg,	J6=    13.494 deg
};
P[12]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   218.008 deg,
	J4=   113.971 deg,	J5=  -118.853 deg,	J6=  -224.551 deg
};
P[13]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   218.008 deg,
	J4=   114.971 deg,	J5=  -118.853 deg,	J6=  -223.551 deg
};
P[14]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   148.136 deg,
	J4=    35.358 deg,	J5=  -139.275 deg,	J6=    31.819 deg
};
P[15]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   149.136 deg,
	J4=    36.358 deg,	J5=  -139.275 deg,	J6=    31.819 deg
};
P[16]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   171.317 deg,
	J4=     6.420 deg,	J5=     5.906 deg,	J6=   169.709 deg
};
P[17]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   171.317 deg,
	J4=     7.420 deg,	J5=     4.906 deg,	J6=   169.709 deg
};
P[18]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   178.211 deg,
	J4=     3.324 deg,	J5=     4.903 deg,	J6=   176.141 deg
};
P[19]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   178.211 deg,
	J4=     4.324 deg,	J5=     4.903 deg,	J6=   176.141 deg
};
P[20]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   158.470 deg,
	J4=   -34.462 deg,	J5=    26.377 deg,	J6=   208.491 deg
};
P[21]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   159.470 deg,
	J4=   -33.462 deg,	J5=    25.377 deg,	J6=   208.491 deg
};
P[22]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   120.246 deg,
	J4=  -184.491 deg,	J5=   122.498 deg,	J6=   173.268 deg
};
P[23]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   121.246 deg,
	J4=  -183.491 deg,	J5=   121.498 deg,	J6=   174.268 deg
};
P[24]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    77.484 deg,
	J4=  -152.066 deg,	J5=   -92.403 deg,	J6=    -2.923 deg
};
P[25]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    78.484 deg,
	J4=  -152.066 deg,	J5=   -92.403 deg,	J6=    -1.923 deg
};
P[26]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    38.808 deg,
	J4=  -131.184 deg,	J5=  -129.218 deg,	J6=    38.988 deg
};
P[27]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    39.808 deg,
	J4=  -131.184 deg,	J5=  -129.218 deg,	J6=    38.988 deg
};
P[28]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -39.892 deg,
	J4=    32.959 deg,	J5=  -137.075 deg,	J6=   207.817 deg
};
P[29]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -38.892 deg,
	J4=    32.959 deg,	J5=  -137.075 deg,	J6=   207.817 deg
};
P[30]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=     2.356 deg,
	J4=   154.846 deg,	J5=     1.158 deg,	J6=   202.169 deg
};
P[31]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=     2.356 deg,
	J4=   154.846 deg,	J5=     0.158 deg,	J6=   203.169 deg
};
P[32]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    44.159 deg,
	J4=   177.986 deg,	J5=  -137.715 deg,	J6=     0.848 deg
};
P[33]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    44.159 deg,
	J4=   177.986 deg,	J5=  -137.715 deg,	J6=     1.848 deg
};
P[34]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -54.611 deg,
	J4=    36.366 deg,	J5=  -116.945 deg,	J6=  -160.368 deg
};
P[35]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -53.611 deg,
	J4=    37.366 deg,	J5=  -117.945 deg,	J6=  -159.368 deg
};
P[36]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -26.187 deg,
	J4=  -124.430 deg,	J5=   -38.880 deg,	J6=  -230.737 deg
};
P[37]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -26.187 deg,
	J4=  -123.430 deg,	J5=   -39.880 deg,	J6=  -229.737 deg
};
P[38]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -25.888 deg,
	J4=  -117.725 deg,	J5=   136.593 deg,	J6=    55.825 deg
};
P[39]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -25.888 deg,
	J4=  -117.725 deg,	J5=   135.593 deg,	J6=    55.825 deg
};
P[40]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -11.202 deg,
	J4=   -18.907 deg,	J5=     6.935 deg,	J6=    17.707 deg
};
P[41]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -11.202 deg,
	J4=   -18.907 deg,	J5=     6.935 deg,	J6=    18.707 deg
};
P[42]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    23.472 deg,
	J4=    24.507 deg,	J5=   -25.109 deg,	J6=   -21.515 deg
};
P[43]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    23.472 deg,
	J4=    24.507 deg,	J5=   -25.109 deg,	J6=   -20.515 deg
};
P[44]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    49.227 deg,
	J4=   171.390 deg,	J5=    56.910 deg,	J6=  -168.017 deg
};
P[45]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    49.227 deg,
	J4=   171.390 deg,	J5=    55.910 deg,	J6=  -167.017 deg
};
P[46]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    -5.920 deg,
	J4=    88.561 deg,	J5=    74.072 deg,	J6=   -84.423 deg
};
P[47]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    -4.920 deg,
	J4=    89.561 deg,	J5=    73.072 deg,	J6=   -84.423 deg
};
P[48]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -56.146 deg,
	J4=   189.433 deg,	J5=   118.033 deg,	J6=    -0.383 deg
};
P[49]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -55.146 deg,
	J4=   189.433 deg,	J5=   117.033 deg,	J6=    -0.383 deg
};
P[50]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -145.010 deg,
	J4=    34.477 deg,	J5=   -48.805 deg,	J6=   159.857 deg
};
P[51]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -144.010 deg,
	J4=    35.477 deg,	J5=   -48.805 deg,	J6=   159.857 deg
};
P[52]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -181.869 deg,
	J4=   -89.870 deg,	J5=   -83.907 deg,	J6=   -91.449 deg
};
P[53]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -180.869 deg,
	J4=   -88.870 deg,	J5=   -83.907 deg,	J6=   -90.449 deg
};
/END
