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
  42:  ! J4+ J5+ J6+. ;
  43:  ! Dwell 3.2 s at each ;
  44:  ! capture: settling 1 ;
  45:  ! s (stated default) + ;
  46:  ! the pendant's 2 s ;
  47:  ! still window + 2 ;
  48:  ! sensor periods. ;
  49:  ! Predicted robot time ;
  50:  ! 5.6 min (motion 122 ;
  51:  ! s, dwell 83 s, ;
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
  79:  WAIT   3.20(sec) ;
  80:  ! zerocal stage 1: ;
  81:  ! joint 1 turned by ;
  82:  ! 180 deg ;
  83:J P[4] 10% FINE ;
  84:  WAIT   3.20(sec) ;
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
 106:  WAIT   3.20(sec) ;
 107:  ! zerocal stage 2: ;
 108:  ! pose 2 of 24 ;
 109:J P[8] 10% FINE ;
 110:J P[9] 10% FINE ;
 111:  WAIT   3.20(sec) ;
 112:  ! zerocal stage 2: ;
 113:  ! pose 3 of 24 ;
 114:J P[10] 10% FINE ;
 115:J P[11] 10% FINE ;
 116:  WAIT   3.20(sec) ;
 117:  ! zerocal stage 2: ;
 118:  ! pose 4 of 24 ;
 119:J P[12] 10% FINE ;
 120:J P[13] 10% FINE ;
 121:  WAIT   3.20(sec) ;
 122:  ! zerocal stage 2: ;
 123:  ! pose 5 of 24 ;
 124:J P[14] 10% FINE ;
 125:J P[15] 10% FINE ;
 126:  WAIT   3.20(sec) ;
 127:  ! zerocal stage 2: ;
 128:  ! pose 6 of 24 ;
 129:J P[16] 10% FINE ;
 130:J P[17] 10% FINE ;
 131:  WAIT   3.20(sec) ;
 132:  ! zerocal stage 2: ;
 133:  ! pose 7 of 24 ;
 134:J P[18] 10% FINE ;
 135:J P[19] 10% FINE ;
 136:  WAIT   3.20(sec) ;
 137:  ! zerocal stage 2: ;
 138:  ! pose 8 of 24 ;
 139:J P[20] 10% FINE ;
 140:J P[21] 10% FINE ;
 141:  WAIT   3.20(sec) ;
 142:  ! zerocal stage 2: ;
 143:  ! pose 9 of 24 ;
 144:J P[22] 10% FINE ;
 145:J P[23] 10% FINE ;
 146:  WAIT   3.20(sec) ;
 147:  ! zerocal stage 2: ;
 148:  ! pose 10 of 24 ;
 149:J P[24] 10% FINE ;
 150:J P[25] 10% FINE ;
 151:  WAIT   3.20(sec) ;
 152:  ! zerocal stage 2: ;
 153:  ! pose 11 of 24 ;
 154:J P[26] 10% FINE ;
 155:J P[27] 10% FINE ;
 156:  WAIT   3.20(sec) ;
 157:  ! zerocal stage 2: ;
 158:  ! pose 12 of 24 ;
 159:J P[28] 10% FINE ;
 160:J P[29] 10% FINE ;
 161:  WAIT   3.20(sec) ;
 162:  ! zerocal stage 2: ;
 163:  ! pose 13 of 24 ;
 164:J P[30] 10% FINE ;
 165:J P[31] 10% FINE ;
 166:  WAIT   3.20(sec) ;
 167:  ! zerocal stage 2: ;
 168:  ! pose 14 of 24 ;
 169:J P[32] 10% FINE ;
 170:J P[33] 10% FINE ;
 171:  WAIT   3.20(sec) ;
 172:  ! zerocal stage 2: ;
 173:  ! pose 15 of 24 ;
 174:J P[34] 10% FINE ;
 175:J P[35] 10% FINE ;
 176:  WAIT   3.20(sec) ;
 177:  ! zerocal stage 2: ;
 178:  ! pose 16 of 24 ;
 179:J P[36] 10% FINE ;
 180:J P[37] 10% FINE ;
 181:  WAIT   3.20(sec) ;
 182:  ! zerocal stage 2: ;
 183:  ! pose 17 of 24 ;
 184:J P[38] 10% FINE ;
 185:J P[39] 10% FINE ;
 186:  WAIT   3.20(sec) ;
 187:  ! zerocal stage 2: ;
 188:  ! pose 18 of 24 ;
 189:J P[40] 10% FINE ;
 190:J P[41] 10% FINE ;
 191:  WAIT   3.20(sec) ;
 192:  ! zerocal stage 2: ;
 193:  ! pose 19 of 24 ;
 194:J P[42] 10% FINE ;
 195:J P[43] 10% FINE ;
 196:  WAIT   3.20(sec) ;
 197:  ! zerocal stage 2: ;
 198:  ! pose 20 of 24 ;
 199:J P[44] 10% FINE ;
 200:J P[45] 10% FINE ;
 201:  WAIT   3.20(sec) ;
 202:  ! zerocal stage 2: ;
 203:  ! pose 21 of 24 ;
 204:J P[46] 10% FINE ;
 205:J P[47] 10% FINE ;
 206:  WAIT   3.20(sec) ;
 207:  ! zerocal stage 2: ;
 208:  ! pose 22 of 24 ;
 209:J P[48] 10% FINE ;
 210:J P[49] 10% FINE ;
 211:  WAIT   3.20(sec) ;
 212:  ! zerocal stage 2: ;
 213:  ! pose 23 of 24 ;
 214:J P[50] 10% FINE ;
 215:J P[51] 10% FINE ;
 216:  WAIT   3.20(sec) ;
 217:  ! zerocal stage 2: ;
 218:  ! pose 24 of 24 ;
 219:J P[52] 10% FINE ;
 220:J P[53] 10% FINE ;
 221:  WAIT   3.20(sec) ;
 222:  ! zerocal: session ;
 223:  ! done; the pendant ;
 224:  ! shows the result ;
/POS
P[1]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -46.000 deg,	J3=    72.330 deg,
	J4=    -1.000 deg,	J5=    -1.000 deg,	J6=    -1.000 deg
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
	J1=   -91.000 deg,	J2=     0.000 deg,	J3=   -65.298 deg,
	J4=   198.604 deg,	J5=    76.201 deg,	J6=     4.175 deg
};
P[6]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -64.298 deg,
	J4=   198.604 deg,	J5=    76.201 deg,	J6=     4.175 deg
};
P[7]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -64.298 deg,
	J4=   198.604 deg,	J5=   121.201 deg,	J6=     4.175 deg
};
P[8]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    -4.707 deg,
	J4=    88.114 deg,	J5=    71.550 deg,	J6=   -85.111 deg
};
P[9]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    -4.707 deg,
	J4=    89.114 deg,	J5=    72.550 deg,	J6=   -84.111 deg
};
P[10]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -23.154 deg,
	J4=    55.544 deg,	J5=    38.837 deg,	J6=   -51.011 deg
};
P[11]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -22.154 deg,
	J4=    56.544 deg,	J5=    39.837 deg,	J6=   -51.011 deg
};
P[12]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    23.562 deg,
	J4=    23.384 deg,	J5=   -25.930 deg,	J6=   -20.439 deg
};
P[13]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    23.562 deg,
	J4=    24.384 deg,	J5=   -24.930 deg,	J6=   -20.439 deg
};
P[14]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    -4.712 deg,
	J4=    85.939 deg,	J5=  -130.987 deg,	J6=   -98.862 deg
};
P[15]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    -3.712 deg,
	J4=    85.939 deg,	J5=  -129.987 deg,	J6=   -97.862 deg
};
P[16]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    44.158 deg,
	J4=   177.096 deg,	J5=  -137.731 deg,	J6=     1.841 deg
};
P[17]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    44.158 deg,
	J4=   177.096 deg,	J5=  -136.731 deg,	J6=     1.841 deg
};
P[18]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -39.529 deg,
	J4=    31.794 deg,	J5=  -136.096 deg,	J6=   207.047 deg
};
P[19]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -38.529 deg,
	J4=    32.794 deg,	J5=  -136.096 deg,	J6=   207.047 deg
};
P[20]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -142.617 deg,
	J4=  -114.937 deg,	J5=  -118.730 deg,	J6=   223.978 deg
};
P[21]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -141.617 deg,
	J4=  -113.937 deg,	J5=  -118.730 deg,	J6=   223.978 deg
};
P[22]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -134.852 deg,
	J4=  -195.576 deg,	J5=  -136.559 deg,	J6=   170.907 deg
};
P[23]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -134.852 deg,
	J4=  -194.576 deg,	J5=  -135.559 deg,	J6=   171.907 deg
};
P[24]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -180.887 deg,
	J4=   -88.425 deg,	J5=   -83.307 deg,	J6=   -91.114 deg
};
P[25]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -179.887 deg,
	J4=   -88.425 deg,	J5=   -83.307 deg,	J6=   -90.114 deg
};
P[26]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -178.689 deg,
	J4=    90.174 deg,	J5=   -92.305 deg,	J6=    91.495 deg
};
P[27]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -178.689 deg,
	J4=    90.174 deg,	J5=   -91.305 deg,	J6=    91.495 deg
};
P[28]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -150.403 deg,
	J4=   -57.759 deg,	J5=   133.802 deg,	J6=   -51.643 deg
};
P[29]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -150.403 deg,
	J4=   -56.759 deg,	J5=   133.802 deg,	J6=   -50.643 deg
};
P[30]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -25.881 deg,
	J4=  -123.813 deg,	J5=   -40.595 deg,	J6=  -229.886 deg
};
P[31]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -25.881 deg,
	J4=  -122.813 deg,	J5=   -39.595 deg,	J6=  -228.886 deg
};
P[32]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    -7.698 deg,
	J4=  -184.812 deg,	J5=   -12.935 deg,	J6=  -182.220 deg
};
P[33]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    -7.698 deg,
	J4=  -183.812 deg,	J5=   -12.935 deg,	J6=  -182.220 deg
};
P[34]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -22.215 deg,
	J4=  -133.450 deg,	J5=   -21.629 deg,	J6=   130.803 deg
};
P[35]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -21.215 deg,
	J4=  -133.450 deg,	J5=   -20.629 deg,	J6=   130.803 deg
};
P[36]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    25.706 deg,
	J4=   -61.914 deg,	J5=   137.043 deg,	J6=   124.764 deg
};
P[37]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    25.706 deg,
	J4=   -61.914 deg,	J5=   137.043 deg,	J6=   125.764 deg
};
P[38]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   133.450 deg,
	J4=   164.550 deg,	J5=   -49.631 deg,	J6=     7.319 deg
};
P[39]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   133.450 deg,
	J4=   164.550 deg,	J5=   -48.631 deg,	J6=     8.319 deg
};
P[40]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   159.267 deg,
	J4=   162.492 deg,	J5=   -18.996 deg,	J6=    13.445 deg
};
P[41]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   159.267 deg,
	J4=   163.492 deg,	J5=   -18.996 deg,	J6=    13.445 deg
};
P[42]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   194.459 deg,
	J4=   111.544 deg,	J5=    18.832 deg,	J6=    71.013 deg
};
P[43]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   194.459 deg,
	J4=   112.544 deg,	J5=    18.832 deg,	J6=    71.013 deg
};
P[44]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   180.007 deg,
	J4=    22.153 deg,	J5=    -0.693 deg,	J6=   159.207 deg
};
P[45]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   181.007 deg,
	J4=    23.153 deg,	J5=     0.307 deg,	J6=   159.207 deg
};
P[46]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   176.626 deg,
	J4=     3.302 deg,	J5=     4.868 deg,	J6=   175.489 deg
};
P[47]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   177.626 deg,
	J4=     4.302 deg,	J5=     4.868 deg,	J6=   175.489 deg
};
P[48]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   228.372 deg,
	J4=   -34.348 deg,	J5=   -54.164 deg,	J6=   200.825 deg
};
P[49]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   228.372 deg,
	J4=   -33.348 deg,	J5=   -53.164 deg,	J6=   200.825 deg
};
P[50]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   265.719 deg,
	J4=     0.711 deg,	J5=    90.639 deg,	J6=    -0.712 deg
};
P[51]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   265.719 deg,
	J4=     0.711 deg,	J5=    90.639 deg,	J6=     0.288 deg
};
P[52]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   221.177 deg,
	J4=    47.347 deg,	J5=   121.592 deg,	J6=    31.098 deg
};
P[53]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   222.177 deg,
	J4=    47.347 deg,	J5=   121.592 deg,	J6=    31.098 deg
};
/END
