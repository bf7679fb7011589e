/PROG  ZC_CHK20
/ATTR
OWNER		= MNEDITOR;
COMMENT		= "zerocal";
PROG_SIZE	= 0;
CREATE		= DATE 23-11-14  TIME 22:13:20;
MODIFIED	= DATE 23-11-14  TIME 22:13:20;
FILE_NAME	= ;
VERSION		= 0;
LINE_COUNT	= 174;
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
  10:  ! 24 poses (1, 10, 12, ;
  11:  ! 14, 16), at the ;
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
  47:  ! Closing reversal: ;
  48:  ! the robot parks ;
  49:  ! where the pendant ;
  50:  ! went on the flange ;
  51:  ! and stops; take the ;
  52:  ! pendant off and ;
  53:  ! reverse it on the ;
  54:  ! bench as in stage 0 ;
  55:  ! (two readings, ;
  56:  ! turned 180 deg on ;
  57:  ! the same spot ;
  58:  ! between them). The ;
  59:  ! program ends there. ;
  60:  ! Speed: joint moves ;
  61:  ! at 10 % of each ;
  62:  ! joint's maximum ;
  63:  ! speed, exact stops. ;
  64:  ! Dwell 3.1 s at each ;
  65:  ! capture: settling 1 ;
  66:  ! s (stated default) + ;
  67:  ! the pendant's 2 s ;
  68:  ! still window + 2 ;
  69:  ! sensor periods of ;
  70:  ! 0.05 s. ;
  71:  ! Predicted robot time ;
  72:  ! 3.5 min, the closing ;
  73:  ! reversal included: ;
  74:  ! motion 45 s, dwell ;
  75:  ! 37 s (12 captures), ;
  76:  ! 2 mountings 120 s, ;
  77:  ! operator OKs 10 s. ;
  78:  ! WARNING: the path is ;
  79:  ! NOT checked for ;
  80:  ! collisions with the ;
  81:  ! cell, the pendant or ;
  82:  ! its bracket. Check ;
  83:  ! the cell, then step ;
  84:  ! through the program ;
  85:  ! once at reduced ;
  86:  ! speed (T1) before ;
  87:  ! running it. ;
  88:  ! zerocal check: the ;
  89:  ! pendant goes on the ;
  90:  ! flange here, tilted ;
  91:  ! past its range so ;
  92:  ! that it cannot ;
  93:  ! capture yet ;
  94:J P[1] 10% FINE ;
  95:  MESSAGE[zerocal: clip the] ;
  96:  MESSAGE[pendant to the] ;
  97:  MESSAGE[flange (its screen] ;
  98:  MESSAGE[at POSE 1), then] ;
  99:  MESSAGE[continue.] ;
 100:  PAUSE ;
 101:  ! zerocal check: pose ;
 102:  ! 1 of 24, captured ;
 103:  ! from below, then ;
 104:  ! from above ;
 105:J P[2] 10% FINE ;
 106:J P[3] 10% FINE ;
 107:  WAIT   3.10(sec) ;
 108:J P[4] 10% FINE ;
 109:J P[5] 10% FINE ;
 110:  WAIT   3.10(sec) ;
 111:  ! zerocal check: pose ;
 112:  ! 10 of 24, captured ;
 113:  ! from below, then ;
 114:  ! from above ;
 115:J P[6] 10% FINE ;
 116:J P[7] 10% FINE ;
 117:  WAIT   3.10(sec) ;
 118:J P[8] 10% FINE ;
 119:J P[9] 10% FINE ;
 120:  WAIT   3.10(sec) ;
 121:  ! zerocal check: pose ;
 122:  ! 12 of 24, captured ;
 123:  ! from below, then ;
 124:  ! from above ;
 125:J P[10] 10% FINE ;
 126:J P[11] 10% FINE ;
 127:  WAIT   3.10(sec) ;
 128:J P[12] 10% FINE ;
 129:J P[13] 10% FINE ;
 130:  WAIT   3.10(sec) ;
 131:  ! zerocal check: pose ;
 132:  ! 14 of 24, captured ;
 133:  ! from below, then ;
 134:  ! from above ;
 135:J P[14] 10% FINE ;
 136:J P[15] 10% FINE ;
 137:  WAIT   3.10(sec) ;
 138:J P[16] 10% FINE ;
 139:J P[17] 10% FINE ;
 140:  WAIT   3.10(sec) ;
 141:  ! zerocal check: pose ;
 142:  ! 16 of 24, captured ;
 143:  ! from below, then ;
 144:  ! from above ;
 145:J P[18] 10% FINE ;
 146:J P[19] 10% FINE ;
 147:  WAIT   3.10(sec) ;
 148:J P[20] 10% FINE ;
 149:J P[21] 10% FINE ;
 150:  WAIT   3.10(sec) ;
 151:  ! zerocal: the check's ;
 152:  ! poses done; the ;
 153:  ! robot parks where ;
 154:  ! the pendant went on ;
 155:  ! the flange (tilted ;
 156:  ! past its range) for ;
 157:  ! the closing reversal ;
 158:J P[22] 10% FINE ;
 159:  MESSAGE[zerocal: closing] ;
 160:  MESSAGE[reversal: take the] ;
 161:  MESSAGE[pendant off the] ;
 162:  MESSAGE[flange to the bench] ;
 163:  MESSAGE[of stage 0, let it] ;
 164:  MESSAGE[capture, turn it 180] ;
 165:  MESSAGE[deg on the same] ;
 166:  MESSAGE[spot, press OK, let] ;
 167:  MESSAGE[it capture. Then] ;
 168:  MESSAGE[continue.] ;
 169:  PAUSE ;
 170:  ! zerocal: check done; ;
 171:  ! export it from the ;
 172:  ! pendant (zerocal ;
 173:  ! pendant export), ;
 174:  ! then zerocal check ;
/POS
P[1]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -45.000 deg,	J3=   -43.822 deg,
	J4=   -86.555 deg,	J5=   -90.492 deg,	J6=  -265.246 deg
};
P[2]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -1.000 deg,	J3=     0.178 deg,
	J4=   -87.555 deg,	J5=   -91.492 deg,	J6=  -266.246 deg
};
P[3]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=     1.178 deg,
	J4=   -86.555 deg,	J5=   -90.492 deg,	J6=  -265.246 deg
};
P[4]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.000 deg,	J3=     5.178 deg,
	J4=   -82.555 deg,	J5=   -86.492 deg,	J6=  -261.246 deg
};
P[5]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=     1.178 deg,
	J4=   -86.555 deg,	J5=   -90.492 deg,	J6=  -265.246 deg
};
P[6]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -1.000 deg,	J3=  -164.894 deg,
	J4=    -1.253 deg,	J5=   -14.578 deg,	J6=   180.522 deg
};
P[7]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -163.894 deg,
	J4=    -0.253 deg,	J5=   -13.578 deg,	J6=   181.522 deg
};
P[8]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.000 deg,	J3=  -159.894 deg,
	J4=     3.747 deg,	J5=    -9.578 deg,	J6=   185.522 deg
};
P[9]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -163.894 deg,
	J4=    -0.253 deg,	J5=   -13.578 deg,	J6=   181.522 deg
};
P[10]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -1.000 deg,	J3=  -135.714 deg,
	J4=  -195.609 deg,	J5=  -136.596 deg,	J6=   168.448 deg
};
P[11]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -134.714 deg,
	J4=  -194.609 deg,	J5=  -135.596 deg,	J6=   169.448 deg
};
P[12]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.000 deg,	J3=  -130.714 deg,
	J4=  -190.609 deg,	J5=  -131.596 deg,	J6=   173.448 deg
};
P[13]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -134.714 deg,
	J4=  -194.609 deg,	J5=  -135.596 deg,	J6=   169.448 deg
};
P[14]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -1.000 deg,	J3=  -161.448 deg,
	J4=  -152.774 deg,	J5=    26.043 deg,	J6=   -32.434 deg
};
P[15]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -160.448 deg,
	J4=  -151.774 deg,	J5=    27.043 deg,	J6=   -31.434 deg
};
P[16]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.000 deg,	J3=  -156.448 deg,
	J4=  -147.774 deg,	J5=    31.043 deg,	J6=   -27.434 deg
};
P[17]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -160.448 deg,
	J4=  -151.774 deg,	J5=    27.043 deg,	J6=   -31.434 deg
};
P[18]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -1.000 deg,	J3=   -41.081 deg,
	J4=    30.047 deg,	J5=  -137.127 deg,	J6=   203.392 deg
};
P[19]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -40.081 deg,
	J4=    31.047 deg,	J5=  -136.127 deg,	J6=   204.392 deg
};
P[20]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.000 deg,	J3=   -36.081 deg,
	J4=    35.047 deg,	J5=  -132.127 deg,	J6=   208.392 deg
};
P[21]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -40.081 deg,
	J4=    31.047 deg,	J5=  -136.127 deg,	J6=   204.392 deg
};
P[22]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -45.000 deg,	J3=   -43.822 deg,
	J4=   -86.555 deg,	J5=   -90.492 deg,	J6=  -265.246 deg
};
/END
