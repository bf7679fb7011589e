/PROG  ZC_M20IA
/ATTR
OWNER		= MNEDITOR;
COMMENT		= "zerocal";
PROG_SIZE	= 0;
CREATE		= DATE 23-11-14  TIME 22:13:20;
MODIFIED	= DATE 23-11-14  TIME 22:13:20;
FILE_NAME	= ;
VERSION		= 0;
LINE_COUNT	= 144;
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
   7:  ! fanuc-m20ia); 8 ;
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
  50:  ! 3.9 min (motion 72 ;
  51:  ! s, dwell 32 s, ;
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
 104:  ! pose 1 of 8 ;
 105:J P[7] 10% FINE ;
 106:  WAIT   3.20(sec) ;
 107:  ! zerocal stage 2: ;
 108:  ! pose 2 of 8 ;
 109:J P[8] 10% FINE ;
 110:J P[9] 10% FINE ;
 111:  WAIT   3.20(sec) ;
 112:  ! zerocal stage 2: ;
 113:  ! pose 3 of 8 ;
 114:J P[10] 10% FINE ;
 115:J P[11] 10% FINE ;
 116:  WAIT   3.20(sec) ;
 117:  ! zerocal stage 2: ;
 118:  ! pose 4 of 8 ;
 119:J P[12] 10% FINE ;
 120:J P[13] 10% FINE ;
 121:  WAIT   3.20(sec) ;
 122:  ! zerocal stage 2: ;
 123:  ! pose 5 of 8 ;
 124:J P[14] 10% FINE ;
 125:J P[15] 10% FINE ;
 126:  WAIT   3.20(sec) ;
 127:  ! zerocal stage 2: ;
 128:  ! pose 6 of 8 ;
 129:J P[16] 10% FINE ;
 130:J P[17] 10% FINE ;
 131:  WAIT   3.20(sec) ;
 132:  ! zerocal stage 2: ;
 133:  ! pose 7 of 8 ;
 134:J P[18] 10% FINE ;
 135:J P[19] 10% FINE ;
 136:  WAIT   3.20(sec) ;
 137:  ! zerocal stage 2: ;
 138:  ! pose 8 of 8 ;
 139:J P[20] 10% FINE ;
 140:J P[21] 10% FINE ;
 141:  WAIT   3.20(sec) ;
 142:  ! zerocal: session ;
 143:  ! done; the pendant ;
 144:  ! shows the result ;
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
	J1=   -91.000 deg,	J2=     0.000 deg,	J3=   265.624 deg,
	J4=   175.214 deg,	J5=   -62.919 deg,	J6=  -227.575 deg
};
P[6]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   265.624 deg,
	J4=   175.214 deg,	J5=   -61.919 deg,	J6=  -226.575 deg
};
P[7]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   265.624 deg,
	J4=   175.214 deg,	J5=   -16.919 deg,	J6=  -226.575 deg
};
P[8]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   192.437 deg,
	J4=     6.013 deg,	J5=    68.502 deg,	J6=  -263.042 deg
};
P[9]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   193.437 deg,
	J4=     7.013 deg,	J5=    68.502 deg,	J6=  -262.042 deg
};
P[10]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   178.675 deg,
	J4=     0.108 deg,	J5=   102.244 deg,	J6=  -129.897 deg
};
P[11]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   179.675 deg,
	J4=     1.108 deg,	J5=   102.244 deg,	J6=  -129.897 deg
};
P[12]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   205.190 deg,
	J4=  -168.835 deg,	J5=   -68.236 deg,	J6=   -56.512 deg
};
P[13]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   205.190 deg,
	J4=  -167.835 deg,	J5=   -67.236 deg,	J6=   -56.512 deg
};
P[14]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   146.489 deg,
	J4=     0.857 deg,	J5=   110.580 deg,	J6=   130.345 deg
};
P[15]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   147.489 deg,
	J4=     0.857 deg,	J5=   110.580 deg,	J6=   130.345 deg
};
P[16]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -87.897 deg,
	J4=   162.551 deg,	J5=    13.319 deg,	J6=  -223.704 deg
};
P[17]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -86.897 deg,
	J4=   162.551 deg,	J5=    14.319 deg,	J6=  -222.704 deg
};
P[18]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -79.892 deg,
	J4=    67.061 deg,	J5=   -11.414 deg,	J6=     9.591 deg
};
P[19]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -79.892 deg,
	J4=    68.061 deg,	J5=   -10.414 deg,	J6=     9.591 deg
};
P[20]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -169.592 deg,
	J4=  -192.383 deg,	J5=   -81.203 deg,	J6=   235.574 deg
};
P[21]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -168.592 deg,
	J4=  -191.383 deg,	J5=   -80.203 deg,	J6=   235.574 deg
};
/END
