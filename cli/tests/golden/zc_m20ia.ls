/PROG  ZC_M20IA
/ATTR
OWNER		= MNEDITOR;
COMMENT		= "zerocal";
PROG_SIZE	= 0;
CREATE		= DATE 23-11-14  TIME 22:13:20;
MODIFIED	= DATE 23-11-14  TIME 22:13:20;
FILE_NAME	= ;
VERSION		= 0;
LINE_COUNT	= 406;
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
  13:  ! Every pose is ;
  14:  ! captured twice: ;
  15:  ! first with every ;
  16:  ! joint arriving ;
  17:  ! moving positive ;
  18:  ! (from 1 deg below), ;
  19:  ! then, after every ;
  20:  ! joint has gone 4 deg ;
  21:  ! past it, moving ;
  22:  ! negative (from ;
  23:  ! above). The pendant ;
  24:  ! averages the two: ;
  25:  ! the middle of every ;
  26:  ! gear's backlash. ;
  27:  ! Stop: clip the ;
  28:  ! pendant to the upper ;
  29:  ! arm (the robot ;
  30:  ! stands with the ;
  31:  ! pendant tilted past ;
  32:  ! its range, so it ;
  33:  ! cannot capture ;
  34:  ! early). Stage 1: the ;
  35:  ! stage-1 pose twice, ;
  36:  ! then joint 1 turned ;
  37:  ! by 180 deg twice (an ;
  38:  ! OK on the pendant ;
  39:  ! arms the first). ;
  40:  ! Stop: move the ;
  41:  ! pendant to the ;
  42:  ! flange (tilted ;
  43:  ! again). Stage 2: the ;
  44:  ! plan's poses in its ;
  45:  ! order, twice each; ;
  46:  ! load the same plan ;
  47:  ! into the pendant ;
  48:  ! (plan set). ;
  49:  ! Closing reversal: ;
  50:  ! the robot parks ;
  51:  ! where the pendant ;
  52:  ! went on the flange ;
  53:  ! and stops; take the ;
  54:  ! pendant off and ;
  55:  ! reverse it on the ;
  56:  ! bench as in stage 0 ;
  57:  ! (two readings, ;
  58:  ! turned 180 deg on ;
  59:  ! the same spot ;
  60:  ! between them). The ;
  61:  ! program ends there. ;
  62:  ! Speed: joint moves ;
  63:  ! at 10 % of each ;
  64:  ! joint's maximum ;
  65:  ! speed, exact stops. ;
  66:  ! Dwell 3.1 s at each ;
  67:  ! capture: settling 1 ;
  68:  ! s (stated default) + ;
  69:  ! the pendant's 2 s ;
  70:  ! still window + 2 ;
  71:  ! sensor periods of ;
  72:  ! 0.05 s. ;
  73:  ! Predicted robot time ;
  74:  ! 8.9 min, the closing ;
  75:  ! reversal included: ;
  76:  ! motion 165 s, dwell ;
  77:  ! 167 s (54 captures), ;
  78:  ! 3 mountings 180 s, ;
  79:  ! operator OKs 20 s. ;
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
  90:  ! zerocal stage 1: the ;
  91:  ! pendant goes on the ;
  92:  ! upper arm here, ;
  93:  ! tilted past its ;
  94:  ! range so that it ;
  95:  ! cannot capture yet ;
  96:J P[1] 10% FINE ;
  97:  MESSAGE[zerocal: clip the] ;
  98:  MESSAGE[pendant to the upper] ;
  99:  MESSAGE[arm (its screen at] ;
 100:  MESSAGE[STAGE 1), then] ;
 101:  MESSAGE[continue.] ;
 102:  PAUSE ;
 103:  ! zerocal stage 1: the ;
 104:  ! stage-1 pose, ;
 105:  ! captured from below, ;
 106:  ! then from above ;
 107:J P[2] 10% FINE ;
 108:J P[3] 10% FINE ;
 109:  WAIT   3.10(sec) ;
 110:J P[4] 10% FINE ;
 111:J P[5] 10% FINE ;
 112:  WAIT   3.10(sec) ;
 113:  ! zerocal stage 1: ;
 114:  ! joint 1 turned by ;
 115:  ! 180 deg, captured ;
 116:  ! from below, then ;
 117:  ! from above ;
 118:J P[6] 10% FINE ;
 119:J P[7] 10% FINE ;
 120:J P[8] 10% FINE ;
 121:  MESSAGE[zerocal: press OK on] ;
 122:  MESSAGE[the pendant (after] ;
 123:  MESSAGE[the half turn only] ;
 124:  MESSAGE[OK arms it), then] ;
 125:  MESSAGE[continue.] ;
 126:  PAUSE ;
 127:  WAIT   3.10(sec) ;
 128:J P[9] 10% FINE ;
 129:J P[10] 10% FINE ;
 130:  WAIT   3.10(sec) ;
 131:  ! zerocal: joint 1 ;
 132:  ! back; the pendant ;
 133:  ! goes from the upper ;
 134:  ! arm to the flange ;
 135:  ! here, both tilted ;
 136:  ! past its range ;
 137:J P[11] 10% FINE ;
 138:  MESSAGE[zerocal: move the] ;
 139:  MESSAGE[pendant from the] ;
 140:  MESSAGE[upper arm to the] ;
 141:  MESSAGE[flange (its screen] ;
 142:  MESSAGE[at POSE 1), then] ;
 143:  MESSAGE[continue.] ;
 144:  PAUSE ;
 145:  ! zerocal stage 2: ;
 146:  ! pose 1 of 24, ;
 147:  ! captured from below, ;
 148:  ! then from above ;
 149:J P[12] 10% FINE ;
 150:J P[13] 10% FINE ;
 151:  WAIT   3.10(sec) ;
 152:J P[14] 10% FINE ;
 153:J P[15] 10% FINE ;
 154:  WAIT   3.10(sec) ;
 155:  ! zerocal stage 2: ;
 156:  ! pose 2 of 24, ;
 157:  ! captured from below, ;
 158:  ! then from above ;
 159:J P[16] 10% FINE ;
 160:J P[17] 10% FINE ;
 161:  WAIT   3.10(sec) ;
 162:J P[18] 10% FINE ;
 163:J P[19] 10% FINE ;
 164:  WAIT   3.10(sec) ;
 165:  ! zerocal stage 2: ;
 166:  ! pose 3 of 24, ;
 167:  ! captured from below, ;
 168:  ! then from above ;
 169:J P[20] 10% FINE ;
 170:J P[21] 10% FINE ;
 171:  WAIT   3.10(sec) ;
 172:J P[22] 10% FINE ;
 173:J P[23] 10% FINE ;
 174:  WAIT   3.10(sec) ;
 175:  ! zerocal stage 2: ;
 176:  ! pose 4 of 24, ;
 177:  ! captured from below, ;
 178:  ! then from above ;
 179:J P[24] 10% FINE ;
 180:J P[25] 10% FINE ;
 181:  WAIT   3.10(sec) ;
 182:J P[26] 10% FINE ;
 183:J P[27] 10% FINE ;
 184:  WAIT   3.10(sec) ;
 185:  ! zerocal stage 2: ;
 186:  ! pose 5 of 24, ;
 187:  ! captured from below, ;
 188:  ! then from above ;
 189:J P[28] 10% FINE ;
 190:J P[29] 10% FINE ;
 191:  WAIT   3.10(sec) ;
 192:J P[30] 10% FINE ;
 193:J P[31] 10% FINE ;
 194:  WAIT   3.10(sec) ;
 195:  ! zerocal stage 2: ;
 196:  ! pose 6 of 24, ;
 197:  ! captured from below, ;
 198:  ! then from above ;
 199:J P[32] 10% FINE ;
 200:J P[33] 10% FINE ;
 201:  WAIT   3.10(sec) ;
 202:J P[34] 10% FINE ;
 203:J P[35] 10% FINE ;
 204:  WAIT   3.10(sec) ;
 205:  ! zerocal stage 2: ;
 206:  ! pose 7 of 24, ;
 207:  ! captured from below, ;
 208:  ! then from above ;
 209:J P[36] 10% FINE ;
 210:J P[37] 10% FINE ;
 211:  WAIT   3.10(sec) ;
 212:J P[38] 10% FINE ;
 213:J P[39] 10% FINE ;
 214:  WAIT   3.10(sec) ;
 215:  ! zerocal stage 2: ;
 216:  ! pose 8 of 24, ;
 217:  ! captured from below, ;
 218:  ! then from above ;
 219:J P[40] 10% FINE ;
 220:J P[41] 10% FINE ;
 221:  WAIT   3.10(sec) ;
 222:J P[42] 10% FINE ;
 223:J P[43] 10% FINE ;
 224:  WAIT   3.10(sec) ;
 225:  ! zerocal stage 2: ;
 226:  ! pose 9 of 24, ;
 227:  ! captured from below, ;
 228:  ! then from above ;
 229:J P[44] 10% FINE ;
 230:J P[45] 10% FINE ;
 231:  WAIT   3.10(sec) ;
 232:J P[46] 10% FINE ;
 233:J P[47] 10% FINE ;
 234:  WAIT   3.10(sec) ;
 235:  ! zerocal stage 2: ;
 236:  ! pose 10 of 24, ;
 237:  ! captured from below, ;
 238:  ! then from above ;
 239:J P[48] 10% FINE ;
 240:J P[49] 10% FINE ;
 241:  WAIT   3.10(sec) ;
 242:J P[50] 10% FINE ;
 243:J P[51] 10% FINE ;
 244:  WAIT   3.10(sec) ;
 245:  ! zerocal stage 2: ;
 246:  ! pose 11 of 24, ;
 247:  ! captured from below, ;
 248:  ! then from above ;
 249:J P[52] 10% FINE ;
 250:J P[53] 10% FINE ;
 251:  WAIT   3.10(sec) ;
 252:J P[54] 10% FINE ;
 253:J P[55] 10% FINE ;
 254:  WAIT   3.10(sec) ;
 255:  ! zerocal stage 2: ;
 256:  ! pose 12 of 24, ;
 257:  ! captured from below, ;
 258:  ! then from above ;
 259:J P[56] 10% FINE ;
 260:J P[57] 10% FINE ;
 261:  WAIT   3.10(sec) ;
 262:J P[58] 10% FINE ;
 263:J P[59] 10% FINE ;
 264:  WAIT   3.10(sec) ;
 265:  ! zerocal stage 2: ;
 266:  ! pose 13 of 24, ;
 267:  ! captured from below, ;
 268:  ! then from above ;
 269:J P[60] 10% FINE ;
 270:J P[61] 10% FINE ;
 271:  WAIT   3.10(sec) ;
 272:J P[62] 10% FINE ;
 273:J P[63] 10% FINE ;
 274:  WAIT   3.10(sec) ;
 275:  ! zerocal stage 2: ;
 276:  ! pose 14 of 24, ;
 277:  ! captured from below, ;
 278:  ! then from above ;
 279:J P[64] 10% FINE ;
 280:J P[65] 10% FINE ;
 281:  WAIT   3.10(sec) ;
 282:J P[66] 10% FINE ;
 283:J P[67] 10% FINE ;
 284:  WAIT   3.10(sec) ;
 285:  ! zerocal stage 2: ;
 286:  ! pose 15 of 24, ;
 287:  ! captured from below, ;
 288:  ! then from above ;
 289:J P[68] 10% FINE ;
 290:J P[69] 10% FINE ;
 291:  WAIT   3.10(sec) ;
 292:J P[70] 10% FINE ;
 293:J P[71] 10% FINE ;
 294:  WAIT   3.10(sec) ;
 295:  ! zerocal stage 2: ;
 296:  ! pose 16 of 24, ;
 297:  ! captured from below, ;
 298:  ! then from above ;
 299:J P[72] 10% FINE ;
 300:J P[73] 10% FINE ;
 301:  WAIT   3.10(sec) ;
 302:J P[74] 10% FINE ;
 303:J P[75] 10% FINE ;
 304:  WAIT   3.10(sec) ;
 305:  ! zerocal stage 2: ;
 306:  ! pose 17 of 24, ;
 307:  ! captured from below, ;
 308:  ! then from above ;
 309:J P[76] 10% FINE ;
 310:J P[77] 10% FINE ;
 311:  WAIT   3.10(sec) ;
 312:J P[78] 10% FINE ;
 313:J P[79] 10% FINE ;
 314:  WAIT   3.10(sec) ;
 315:  ! zerocal stage 2: ;
 316:  ! pose 18 of 24, ;
 317:  ! captured from below, ;
 318:  ! then from above ;
 319:J P[80] 10% FINE ;
 320:J P[81] 10% FINE ;
 321:  WAIT   3.10(sec) ;
 322:J P[82] 10% FINE ;
 323:J P[83] 10% FINE ;
 324:  WAIT   3.10(sec) ;
 325:  ! zerocal stage 2: ;
 326:  ! pose 19 of 24, ;
 327:  ! captured from below, ;
 328:  ! then from above ;
 329:J P[84] 10% FINE ;
 330:J P[85] 10% FINE ;
 331:  WAIT   3.10(sec) ;
 332:J P[86] 10% FINE ;
 333:J P[87] 10% FINE ;
 334:  WAIT   3.10(sec) ;
 335:  ! zerocal stage 2: ;
 336:  ! pose 20 of 24, ;
 337:  ! captured from below, ;
 338:  ! then from above ;
 339:J P[88] 10% FINE ;
 340:J P[89] 10% FINE ;
 341:  WAIT   3.10(sec) ;
 342:J P[90] 10% FINE ;
 343:J P[91] 10% FINE ;
 344:  WAIT   3.10(sec) ;
 345:  ! zerocal stage 2: ;
 346:  ! pose 21 of 24, ;
 347:  ! captured from below, ;
 348:  ! then from above ;
 349:J P[92] 10% FINE ;
 350:J P[93] 10% FINE ;
 351:  WAIT   3.10(sec) ;
 352:J P[94] 10% FINE ;
 353:J P[95] 10% FINE ;
 354:  WAIT   3.10(sec) ;
 355:  ! zerocal stage 2: ;
 356:  ! pose 22 of 24, ;
 357:  ! captured from below, ;
 358:  ! then from above ;
 359:J P[96] 10% FINE ;
 360:J P[97] 10% FINE ;
 361:  WAIT   3.10(sec) ;
 362:J P[98] 10% FINE ;
 363:J P[99] 10% FINE ;
 364:  WAIT   3.10(sec) ;
 365:  ! zerocal stage 2: ;
 366:  ! pose 23 of 24, ;
 367:  ! captured from below, ;
 368:  ! then from above ;
 369:J P[100] 10% FINE ;
 370:J P[101] 10% FINE ;
 371:  WAIT   3.10(sec) ;
 372:J P[102] 10% FINE ;
 373:J P[103] 10% FINE ;
 374:  WAIT   3.10(sec) ;
 375:  ! zerocal stage 2: ;
 376:  ! pose 24 of 24, ;
 377:  ! captured from below, ;
 378:  ! then from above ;
 379:J P[104] 10% FINE ;
 380:J P[105] 10% FINE ;
 381:  WAIT   3.10(sec) ;
 382:J P[106] 10% FINE ;
 383:J P[107] 10% FINE ;
 384:  WAIT   3.10(sec) ;
 385:  ! zerocal: stage 2 ;
 386:  ! done; the robot ;
 387:  ! parks where the ;
 388:  ! pendant went on the ;
 389:  ! flange (tilted past ;
 390:  ! its range) for the ;
 391:  ! closing reversal ;
 392:J P[108] 10% FINE ;
 393:  MESSAGE[zerocal: closing] ;
 394:  MESSAGE[reversal: take the] ;
 395:  MESSAGE[pendant off the] ;
 396:  MESSAGE[flange to the bench] ;
 397:  MESSAGE[of stage 0, let it] ;
 398:  MESSAGE[capture, turn it 180] ;
 399:  MESSAGE[deg on the same] ;
 400:  MESSAGE[spot, press OK, let] ;
 401:  MESSAGE[it capture. Then] ;
 402:  MESSAGE[continue.] ;
 403:  PAUSE ;
 404:  ! zerocal: session ;
 405:  ! done; the pendant ;
 406:  ! shows the result ;
/POS
P[1]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -45.000 deg,	J3=    58.774 deg,
	J4=     0.000 deg,	J5=     0.000 deg,	J6=     0.000 deg
};
P[2]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -1.000 deg,	J3=    57.774 deg,
	J4=    -1.000 deg,	J5=    -1.000 deg,	J6=    -1.000 deg
};
P[3]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    58.774 deg,
	J4=     0.000 deg,	J5=     0.000 deg,	J6=     0.000 deg
};
P[4]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.000 deg,	J3=    62.774 deg,
	J4=     4.000 deg,	J5=     4.000 deg,	J6=     4.000 deg
};
P[5]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    58.774 deg,
	J4=     0.000 deg,	J5=     0.000 deg,	J6=     0.000 deg
};
P[6]{
   GP1:
	UF : 0, UT : 0,	
	J1=    89.000 deg,	J2=     0.000 deg,	J3=    58.774 deg,
	J4=     0.000 deg,	J5=     0.000 deg,	J6=     0.000 deg
};
P[7]{
   GP1:
	UF : 0, UT : 0,	
	J1=    89.000 deg,	J2=    -1.000 deg,	J3=    57.774 deg,
	J4=    -1.000 deg,	J5=    -1.000 deg,	J6=    -1.000 deg
};
P[8]{
   GP1:
	UF : 0, UT : 0,	
	J1=    90.000 deg,	J2=     0.000 deg,	J3=    58.774 deg,
	J4=     0.000 deg,	J5=     0.000 deg,	J6=     0.000 deg
};
P[9]{
   GP1:
	UF : 0, UT : 0,	
	J1=    94.000 deg,	J2=     4.000 deg,	J3=    62.774 deg,
	J4=     4.000 deg,	J5=     4.000 deg,	J6=     4.000 deg
};
P[10]{
   GP1:
	UF : 0, UT : 0,	
	J1=    90.000 deg,	J2=     0.000 deg,	J3=    58.774 deg,
	J4=     0.000 deg,	J5=     0.000 deg,	J6=     0.000 deg
};
P[11]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -45.000 deg,	J3=   -43.822 deg,
	J4=   -86.555 deg,	J5=   -90.492 deg,	J6=  -265.246 deg
};
P[12]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -1.000 deg,	J3=     0.178 deg,
	J4=   -87.555 deg,	J5=   -91.492 deg,	J6=  -266.246 deg
};
P[13]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=     1.178 deg,
	J4=   -86.555 deg,	J5=   -90.492 deg,	J6=  -265.246 deg
};
P[14]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.000 deg,	J3=     5.178 deg,
	J4=   -82.555 deg,	J5=   -86.492 deg,	J6=  -261.246 deg
};
P[15]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=     1.178 deg,
	J4=   -86.555 deg,	J5=   -90.492 deg,	J6=  -265.246 deg
};
P[16]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -1.000 deg,	J3=   -26.045 deg,
	J4=    -5.199 deg,	J5=    22.623 deg,	J6=     1.437 deg
};
P[17]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -25.045 deg,
	J4=    -4.199 deg,	J5=    23.623 deg,	J6=     2.437 deg
};
P[18]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.000 deg,	J3=   -21.045 deg,
	J4=    -0.199 deg,	J5=    27.623 deg,	J6=     6.437 deg
};
P[19]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -25.045 deg,
	J4=    -4.199 deg,	J5=    23.623 deg,	J6=     2.437 deg
};
P[20]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -1.000 deg,	J3=     6.063 deg,
	J4=   -96.484 deg,	J5=    90.919 deg,	J6=   100.661 deg
};
P[21]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=     7.063 deg,
	J4=   -95.484 deg,	J5=    91.919 deg,	J6=   101.661 deg
};
P[22]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.000 deg,	J3=    11.063 deg,
	J4=   -91.484 deg,	J5=    95.919 deg,	J6=   105.661 deg
};
P[23]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=     7.063 deg,
	J4=   -95.484 deg,	J5=    91.919 deg,	J6=   101.661 deg
};
P[24]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -1.000 deg,	J3=     6.618 deg,
	J4=    90.322 deg,	J5=   120.054 deg,	J6=   258.800 deg
};
P[25]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=     7.618 deg,
	J4=    91.322 deg,	J5=   121.054 deg,	J6=   259.800 deg
};
P[26]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.000 deg,	J3=    11.618 deg,
	J4=    95.322 deg,	J5=   125.054 deg,	J6=   263.800 deg
};
P[27]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=     7.618 deg,
	J4=    91.322 deg,	J5=   121.054 deg,	J6=   259.800 deg
};
P[28]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -1.000 deg,	J3=    56.693 deg,
	J4=   157.290 deg,	J5=    58.281 deg,	J6=   192.060 deg
};
P[29]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    57.693 deg,
	J4=   158.290 deg,	J5=    59.281 deg,	J6=   193.060 deg
};
P[30]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.000 deg,	J3=    61.693 deg,
	J4=   162.290 deg,	J5=    63.281 deg,	J6=   197.060 deg
};
P[31]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    57.693 deg,
	J4=   158.290 deg,	J5=    59.281 deg,	J6=   193.060 deg
};
P[32]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -1.000 deg,	J3=    19.922 deg,
	J4=    21.700 deg,	J5=   -27.161 deg,	J6=   -22.825 deg
};
P[33]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    20.922 deg,
	J4=    22.700 deg,	J5=   -26.161 deg,	J6=   -21.825 deg
};
P[34]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.000 deg,	J3=    24.922 deg,
	J4=    26.700 deg,	J5=   -22.161 deg,	J6=   -17.825 deg
};
P[35]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    20.922 deg,
	J4=    22.700 deg,	J5=   -26.161 deg,	J6=   -21.825 deg
};
P[36]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -1.000 deg,	J3=    -6.874 deg,
	J4=    82.791 deg,	J5=  -131.084 deg,	J6=   -99.816 deg
};
P[37]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    -5.874 deg,
	J4=    83.791 deg,	J5=  -130.084 deg,	J6=   -98.816 deg
};
P[38]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.000 deg,	J3=    -1.874 deg,
	J4=    87.791 deg,	J5=  -126.084 deg,	J6=   -94.816 deg
};
P[39]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    -5.874 deg,
	J4=    83.791 deg,	J5=  -130.084 deg,	J6=   -98.816 deg
};
P[40]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -1.000 deg,	J3=   -50.777 deg,
	J4=   159.511 deg,	J5=   -53.698 deg,	J6=  -170.020 deg
};
P[41]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -49.777 deg,
	J4=   160.511 deg,	J5=   -52.698 deg,	J6=  -169.020 deg
};
P[42]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.000 deg,	J3=   -45.777 deg,
	J4=   164.511 deg,	J5=   -48.698 deg,	J6=  -165.020 deg
};
P[43]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -49.777 deg,
	J4=   160.511 deg,	J5=   -52.698 deg,	J6=  -169.020 deg
};
P[44]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -1.000 deg,	J3=  -152.392 deg,
	J4=    92.914 deg,	J5=   -98.471 deg,	J6=   117.398 deg
};
P[45]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -151.392 deg,
	J4=    93.914 deg,	J5=   -97.471 deg,	J6=   118.398 deg
};
P[46]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.000 deg,	J3=  -147.392 deg,
	J4=    97.914 deg,	J5=   -93.471 deg,	J6=   122.398 deg
};
P[47]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -151.392 deg,
	J4=    93.914 deg,	J5=   -97.471 deg,	J6=   118.398 deg
};
P[48]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -1.000 deg,	J3=  -164.894 deg,
	J4=    -1.253 deg,	J5=   -14.578 deg,	J6=   180.522 deg
};
P[49]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -163.894 deg,
	J4=    -0.253 deg,	J5=   -13.578 deg,	J6=   181.522 deg
};
P[50]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.000 deg,	J3=  -159.894 deg,
	J4=     3.747 deg,	J5=    -9.578 deg,	J6=   185.522 deg
};
P[51]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -163.894 deg,
	J4=    -0.253 deg,	J5=   -13.578 deg,	J6=   181.522 deg
};
P[52]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -1.000 deg,	J3=  -142.360 deg,
	J4=  -115.578 deg,	J5=  -119.948 deg,	J6=   220.229 deg
};
P[53]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -141.360 deg,
	J4=  -114.578 deg,	J5=  -118.948 deg,	J6=   221.229 deg
};
P[54]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.000 deg,	J3=  -137.360 deg,
	J4=  -110.578 deg,	J5=  -114.948 deg,	J6=   225.229 deg
};
P[55]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -141.360 deg,
	J4=  -114.578 deg,	J5=  -118.948 deg,	J6=   221.229 deg
};
P[56]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -1.000 deg,	J3=  -135.714 deg,
	J4=  -195.609 deg,	J5=  -136.596 deg,	J6=   168.448 deg
};
P[57]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -134.714 deg,
	J4=  -194.609 deg,	J5=  -135.596 deg,	J6=   169.448 deg
};
P[58]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.000 deg,	J3=  -130.714 deg,
	J4=  -190.609 deg,	J5=  -131.596 deg,	J6=   173.448 deg
};
P[59]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -134.714 deg,
	J4=  -194.609 deg,	J5=  -135.596 deg,	J6=   169.448 deg
};
P[60]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -1.000 deg,	J3=  -179.959 deg,
	J4=   -90.259 deg,	J5=   -84.908 deg,	J6=   -92.111 deg
};
P[61]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -178.959 deg,
	J4=   -89.259 deg,	J5=   -83.908 deg,	J6=   -91.111 deg
};
P[62]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.000 deg,	J3=  -174.959 deg,
	J4=   -85.259 deg,	J5=   -79.908 deg,	J6=   -87.111 deg
};
P[63]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -178.959 deg,
	J4=   -89.259 deg,	J5=   -83.908 deg,	J6=   -91.111 deg
};
P[64]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -1.000 deg,	J3=  -161.448 deg,
	J4=  -152.774 deg,	J5=    26.043 deg,	J6=   -32.434 deg
};
P[65]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -160.448 deg,
	J4=  -151.774 deg,	J5=    27.043 deg,	J6=   -31.434 deg
};
P[66]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.000 deg,	J3=  -156.448 deg,
	J4=  -147.774 deg,	J5=    31.043 deg,	J6=   -27.434 deg
};
P[67]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -160.448 deg,
	J4=  -151.774 deg,	J5=    27.043 deg,	J6=   -31.434 deg
};
P[68]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -1.000 deg,	J3=  -149.275 deg,
	J4=  -177.273 deg,	J5=    28.944 deg,	J6=    -2.553 deg
};
P[69]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -148.275 deg,
	J4=  -176.273 deg,	J5=    29.944 deg,	J6=    -1.553 deg
};
P[70]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.000 deg,	J3=  -144.275 deg,
	J4=  -172.273 deg,	J5=    33.944 deg,	J6=     2.447 deg
};
P[71]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=  -148.275 deg,
	J4=  -176.273 deg,	J5=    29.944 deg,	J6=    -1.553 deg
};
P[72]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -1.000 deg,	J3=   -41.081 deg,
	J4=    30.047 deg,	J5=  -137.127 deg,	J6=   203.392 deg
};
P[73]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -40.081 deg,
	J4=    31.047 deg,	J5=  -136.127 deg,	J6=   204.392 deg
};
P[74]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.000 deg,	J3=   -36.081 deg,
	J4=    35.047 deg,	J5=  -132.127 deg,	J6=   208.392 deg
};
P[75]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -40.081 deg,
	J4=    31.047 deg,	J5=  -136.127 deg,	J6=   204.392 deg
};
P[76]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -1.000 deg,	J3=   -38.614 deg,
	J4=   -86.438 deg,	J5=   -96.246 deg,	J6=   126.094 deg
};
P[77]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -37.614 deg,
	J4=   -85.438 deg,	J5=   -95.246 deg,	J6=   127.094 deg
};
P[78]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.000 deg,	J3=   -33.614 deg,
	J4=   -81.438 deg,	J5=   -91.246 deg,	J6=   131.094 deg
};
P[79]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   -37.614 deg,
	J4=   -85.438 deg,	J5=   -95.246 deg,	J6=   127.094 deg
};
P[80]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -1.000 deg,	J3=    35.901 deg,
	J4=  -132.044 deg,	J5=  -129.411 deg,	J6=    36.127 deg
};
P[81]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    36.901 deg,
	J4=  -131.044 deg,	J5=  -128.411 deg,	J6=    37.127 deg
};
P[82]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.000 deg,	J3=    40.901 deg,
	J4=  -127.044 deg,	J5=  -124.411 deg,	J6=    41.127 deg
};
P[83]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    36.901 deg,
	J4=  -131.044 deg,	J5=  -128.411 deg,	J6=    37.127 deg
};
P[84]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -1.000 deg,	J3=    91.785 deg,
	J4=   -65.576 deg,	J5=   -91.734 deg,	J6=    -2.808 deg
};
P[85]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    92.785 deg,
	J4=   -64.576 deg,	J5=   -90.734 deg,	J6=    -1.808 deg
};
P[86]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.000 deg,	J3=    96.785 deg,
	J4=   -60.576 deg,	J5=   -86.734 deg,	J6=     2.192 deg
};
P[87]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=    92.785 deg,
	J4=   -64.576 deg,	J5=   -90.734 deg,	J6=    -1.808 deg
};
P[88]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -1.000 deg,	J3=   142.843 deg,
	J4=    33.403 deg,	J5=  -139.288 deg,	J6=    29.024 deg
};
P[89]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   143.843 deg,
	J4=    34.403 deg,	J5=  -138.288 deg,	J6=    30.024 deg
};
P[90]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.000 deg,	J3=   147.843 deg,
	J4=    38.403 deg,	J5=  -134.288 deg,	J6=    34.024 deg
};
P[91]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   143.843 deg,
	J4=    34.403 deg,	J5=  -138.288 deg,	J6=    30.024 deg
};
P[92]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -1.000 deg,	J3=   221.052 deg,
	J4=    28.243 deg,	J5=   -46.756 deg,	J6=  -202.673 deg
};
P[93]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   222.052 deg,
	J4=    29.243 deg,	J5=   -45.756 deg,	J6=  -201.673 deg
};
P[94]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.000 deg,	J3=   226.052 deg,
	J4=    33.243 deg,	J5=   -41.756 deg,	J6=  -197.673 deg
};
P[95]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   222.052 deg,
	J4=    29.243 deg,	J5=   -45.756 deg,	J6=  -201.673 deg
};
P[96]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -1.000 deg,	J3=   176.833 deg,
	J4=    92.496 deg,	J5=    61.580 deg,	J6=  -265.062 deg
};
P[97]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   177.833 deg,
	J4=    93.496 deg,	J5=    62.580 deg,	J6=  -264.062 deg
};
P[98]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.000 deg,	J3=   181.833 deg,
	J4=    97.496 deg,	J5=    66.580 deg,	J6=  -260.062 deg
};
P[99]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   177.833 deg,
	J4=    93.496 deg,	J5=    62.580 deg,	J6=  -264.062 deg
};
P[100]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -1.000 deg,	J3=   210.901 deg,
	J4=   181.689 deg,	J5=    31.828 deg,	J6=    -4.588 deg
};
P[101]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   211.901 deg,
	J4=   182.689 deg,	J5=    32.828 deg,	J6=    -3.588 deg
};
P[102]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.000 deg,	J3=   215.901 deg,
	J4=   186.689 deg,	J5=    36.828 deg,	J6=     0.412 deg
};
P[103]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   211.901 deg,
	J4=   182.689 deg,	J5=    32.828 deg,	J6=    -3.588 deg
};
P[104]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -1.000 deg,	J3=   221.192 deg,
	J4=    29.200 deg,	J5=   134.404 deg,	J6=    19.433 deg
};
P[105]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   222.192 deg,
	J4=    30.200 deg,	J5=   135.404 deg,	J6=    20.433 deg
};
P[106]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.000 deg,	J3=   226.192 deg,
	J4=    34.200 deg,	J5=   139.404 deg,	J6=    24.433 deg
};
P[107]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.000 deg,	J3=   222.192 deg,
	J4=    30.200 deg,	J5=   135.404 deg,	J6=    20.433 deg
};
P[108]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -45.000 deg,	J3=   -43.822 deg,
	J4=   -86.555 deg,	J5=   -90.492 deg,	J6=  -265.246 deg
};
/END
