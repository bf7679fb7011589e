/PROG  ZC_M20IA
/ATTR
OWNER		= MNEDITOR;
COMMENT		= "zerocal";
PROG_SIZE	= 0;
CREATE		= DATE 23-11-14  TIME 22:13:20;
MODIFIED	= DATE 23-11-14  TIME 22:13:20;
FILE_NAME	= ;
VERSION		= 0;
LINE_COUNT	= 601;
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
   7:  ! fanuc-m20ia); 43 ;
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
  49:  ! Closing bench ;
  50:  ! readings: the robot ;
  51:  ! parks where the ;
  52:  ! pendant went on the ;
  53:  ! flange and stops; ;
  54:  ! take the pendant off ;
  55:  ! and read it on the ;
  56:  ! bench as in stage 0 ;
  57:  ! (4 headings, turned ;
  58:  ! by hand about a ;
  59:  ! quarter turn on the ;
  60:  ! same spot between ;
  61:  ! them). The program ;
  62:  ! ends there. ;
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
  75:  ! 12.6 min, the ;
  76:  ! closing bench ;
  77:  ! readings included: ;
  78:  ! motion 243 s, dwell ;
  79:  ! 291 s (94 captures), ;
  80:  ! 3 mountings 180 s, ;
  81:  ! operator OKs 40 s. ;
  82:  ! WARNING: the path is ;
  83:  ! NOT checked for ;
  84:  ! collisions with the ;
  85:  ! cell, the pendant or ;
  86:  ! its bracket. Check ;
  87:  ! the cell, then step ;
  88:  ! through the program ;
  89:  ! once at reduced ;
  90:  ! speed (T1) before ;
  91:  ! running it. ;
  92:  ! zerocal stage 1: the ;
  93:  ! pendant goes on the ;
  94:  ! upper arm here, ;
  95:  ! tilted past its ;
  96:  ! range so that it ;
  97:  ! cannot capture yet ;
  98:J P[1] 10% FINE ;
  99:  MESSAGE[zerocal: clip the] ;
 100:  MESSAGE[pendant to the upper] ;
 101:  MESSAGE[arm (its screen at] ;
 102:  MESSAGE[STAGE 1), then] ;
 103:  MESSAGE[continue.] ;
 104:  PAUSE ;
 105:  ! zerocal stage 1: the ;
 106:  ! stage-1 pose, ;
 107:  ! captured from below, ;
 108:  ! then from above ;
 109:J P[2] 10% FINE ;
 110:J P[3] 10% FINE ;
 111:  WAIT   3.10(sec) ;
 112:J P[4] 10% FINE ;
 113:J P[5] 10% FINE ;
 114:  WAIT   3.10(sec) ;
 115:  ! zerocal stage 1: ;
 116:  ! joint 1 turned by ;
 117:  ! 180 deg, captured ;
 118:  ! from below, then ;
 119:  ! from above ;
 120:J P[6] 10% FINE ;
 121:J P[7] 10% FINE ;
 122:J P[8] 10% FINE ;
 123:  MESSAGE[zerocal: press OK on] ;
 124:  MESSAGE[the pendant (after] ;
 125:  MESSAGE[the half turn only] ;
 126:  MESSAGE[OK arms it), then] ;
 127:  MESSAGE[continue.] ;
 128:  PAUSE ;
 129:  WAIT   3.10(sec) ;
 130:J P[9] 10% FINE ;
 131:J P[10] 10% FINE ;
 132:  WAIT   3.10(sec) ;
 133:  ! zerocal: joint 1 ;
 134:  ! back; the pendant ;
 135:  ! goes from the upper ;
 136:  ! arm to the flange ;
 137:  ! here, both tilted ;
 138:  ! past its range ;
 139:J P[11] 10% FINE ;
 140:  MESSAGE[zerocal: move the] ;
 141:  MESSAGE[pendant from the] ;
 142:  MESSAGE[upper arm to the] ;
 143:  MESSAGE[flange (its screen] ;
 144:  MESSAGE[at POSE 1), then] ;
 145:  MESSAGE[continue.] ;
 146:  PAUSE ;
 147:  ! zerocal stage 2: ;
 148:  ! pose 1 of 43, ;
 149:  ! captured from below, ;
 150:  ! then from above ;
 151:J P[12] 10% FINE ;
 152:J P[13] 10% FINE ;
 153:  WAIT   3.10(sec) ;
 154:J P[14] 10% FINE ;
 155:J P[15] 10% FINE ;
 156:  WAIT   3.10(sec) ;
 157:  ! zerocal stage 2: ;
 158:  ! pose 2 of 43, ;
 159:  ! captured from below, ;
 160:  ! then from above ;
 161:J P[16] 10% FINE ;
 162:J P[17] 10% FINE ;
 163:  WAIT   3.10(sec) ;
 164:J P[18] 10% FINE ;
 165:J P[19] 10% FINE ;
 166:  WAIT   3.10(sec) ;
 167:  ! zerocal stage 2: ;
 168:  ! pose 3 of 43, ;
 169:  ! captured from below, ;
 170:  ! then from above ;
 171:J P[20] 10% FINE ;
 172:J P[21] 10% FINE ;
 173:  WAIT   3.10(sec) ;
 174:J P[22] 10% FINE ;
 175:J P[23] 10% FINE ;
 176:  WAIT   3.10(sec) ;
 177:  ! zerocal stage 2: ;
 178:  ! pose 4 of 43, ;
 179:  ! captured from below, ;
 180:  ! then from above ;
 181:J P[24] 10% FINE ;
 182:J P[25] 10% FINE ;
 183:  WAIT   3.10(sec) ;
 184:J P[26] 10% FINE ;
 185:J P[27] 10% FINE ;
 186:  WAIT   3.10(sec) ;
 187:  ! zerocal stage 2: ;
 188:  ! pose 5 of 43, ;
 189:  ! captured from below, ;
 190:  ! then from above ;
 191:J P[28] 10% FINE ;
 192:J P[29] 10% FINE ;
 193:  WAIT   3.10(sec) ;
 194:J P[30] 10% FINE ;
 195:J P[31] 10% FINE ;
 196:  WAIT   3.10(sec) ;
 197:  ! zerocal stage 2: ;
 198:  ! pose 6 of 43, ;
 199:  ! captured from below, ;
 200:  ! then from above ;
 201:J P[32] 10% FINE ;
 202:J P[33] 10% FINE ;
 203:  WAIT   3.10(sec) ;
 204:J P[34] 10% FINE ;
 205:J P[35] 10% FINE ;
 206:  WAIT   3.10(sec) ;
 207:  ! zerocal stage 2: ;
 208:  ! pose 7 of 43, ;
 209:  ! captured from below, ;
 210:  ! then from above ;
 211:J P[36] 10% FINE ;
 212:J P[37] 10% FINE ;
 213:  WAIT   3.10(sec) ;
 214:J P[38] 10% FINE ;
 215:J P[39] 10% FINE ;
 216:  WAIT   3.10(sec) ;
 217:  ! zerocal stage 2: ;
 218:  ! pose 8 of 43, ;
 219:  ! captured from below, ;
 220:  ! then from above ;
 221:J P[40] 10% FINE ;
 222:J P[41] 10% FINE ;
 223:  WAIT   3.10(sec) ;
 224:J P[42] 10% FINE ;
 225:J P[43] 10% FINE ;
 226:  WAIT   3.10(sec) ;
 227:  ! zerocal stage 2: ;
 228:  ! pose 9 of 43, ;
 229:  ! captured from below, ;
 230:  ! then from above ;
 231:J P[44] 10% FINE ;
 232:J P[45] 10% FINE ;
 233:  WAIT   3.10(sec) ;
 234:J P[46] 10% FINE ;
 235:J P[47] 10% FINE ;
 236:  WAIT   3.10(sec) ;
 237:  ! zerocal stage 2: ;
 238:  ! pose 10 of 43, ;
 239:  ! captured from below, ;
 240:  ! then from above ;
 241:J P[48] 10% FINE ;
 242:J P[49] 10% FINE ;
 243:  WAIT   3.10(sec) ;
 244:J P[50] 10% FINE ;
 245:J P[51] 10% FINE ;
 246:  WAIT   3.10(sec) ;
 247:  ! zerocal stage 2: ;
 248:  ! pose 11 of 43, ;
 249:  ! captured from below, ;
 250:  ! then from above ;
 251:J P[52] 10% FINE ;
 252:J P[53] 10% FINE ;
 253:  WAIT   3.10(sec) ;
 254:J P[54] 10% FINE ;
 255:J P[55] 10% FINE ;
 256:  WAIT   3.10(sec) ;
 257:  ! zerocal stage 2: ;
 258:  ! pose 12 of 43, ;
 259:  ! captured from below, ;
 260:  ! then from above ;
 261:J P[56] 10% FINE ;
 262:J P[57] 10% FINE ;
 263:  WAIT   3.10(sec) ;
 264:J P[58] 10% FINE ;
 265:J P[59] 10% FINE ;
 266:  WAIT   3.10(sec) ;
 267:  ! zerocal stage 2: ;
 268:  ! pose 13 of 43, ;
 269:  ! captured from below, ;
 270:  ! then from above ;
 271:J P[60] 10% FINE ;
 272:J P[61] 10% FINE ;
 273:  WAIT   3.10(sec) ;
 274:J P[62] 10% FINE ;
 275:J P[63] 10% FINE ;
 276:  WAIT   3.10(sec) ;
 277:  ! zerocal stage 2: ;
 278:  ! pose 14 of 43, ;
 279:  ! captured from below, ;
 280:  ! then from above ;
 281:J P[64] 10% FINE ;
 282:J P[65] 10% FINE ;
 283:  WAIT   3.10(sec) ;
 284:J P[66] 10% FINE ;
 285:J P[67] 10% FINE ;
 286:  WAIT   3.10(sec) ;
 287:  ! zerocal stage 2: ;
 288:  ! pose 15 of 43, ;
 289:  ! captured from below, ;
 290:  ! then from above ;
 291:J P[68] 10% FINE ;
 292:J P[69] 10% FINE ;
 293:  WAIT   3.10(sec) ;
 294:J P[70] 10% FINE ;
 295:J P[71] 10% FINE ;
 296:  WAIT   3.10(sec) ;
 297:  ! zerocal stage 2: ;
 298:  ! pose 16 of 43, ;
 299:  ! captured from below, ;
 300:  ! then from above ;
 301:J P[72] 10% FINE ;
 302:J P[73] 10% FINE ;
 303:  WAIT   3.10(sec) ;
 304:J P[74] 10% FINE ;
 305:J P[75] 10% FINE ;
 306:  WAIT   3.10(sec) ;
 307:  ! zerocal stage 2: ;
 308:  ! pose 17 of 43, ;
 309:  ! captured from below, ;
 310:  ! then from above ;
 311:J P[76] 10% FINE ;
 312:J P[77] 10% FINE ;
 313:  WAIT   3.10(sec) ;
 314:J P[78] 10% FINE ;
 315:J P[79] 10% FINE ;
 316:  WAIT   3.10(sec) ;
 317:  ! zerocal stage 2: ;
 318:  ! pose 18 of 43, ;
 319:  ! captured from below, ;
 320:  ! then from above ;
 321:J P[80] 10% FINE ;
 322:J P[81] 10% FINE ;
 323:  WAIT   3.10(sec) ;
 324:J P[82] 10% FINE ;
 325:J P[83] 10% FINE ;
 326:  WAIT   3.10(sec) ;
 327:  ! zerocal stage 2: ;
 328:  ! pose 19 of 43, ;
 329:  ! captured from below, ;
 330:  ! then from above ;
 331:J P[84] 10% FINE ;
 332:J P[85] 10% FINE ;
 333:  WAIT   3.10(sec) ;
 334:J P[86] 10% FINE ;
 335:J P[87] 10% FINE ;
 336:  WAIT   3.10(sec) ;
 337:  ! zerocal stage 2: ;
 338:  ! pose 20 of 43, ;
 339:  ! captured from below, ;
 340:  ! then from above ;
 341:J P[88] 10% FINE ;
 342:J P[89] 10% FINE ;
 343:  WAIT   3.10(sec) ;
 344:J P[90] 10% FINE ;
 345:J P[91] 10% FINE ;
 346:  WAIT   3.10(sec) ;
 347:  ! zerocal stage 2: ;
 348:  ! pose 21 of 43, ;
 349:  ! captured from below, ;
 350:  ! then from above ;
 351:J P[92] 10% FINE ;
 352:J P[93] 10% FINE ;
 353:  WAIT   3.10(sec) ;
 354:J P[94] 10% FINE ;
 355:J P[95] 10% FINE ;
 356:  WAIT   3.10(sec) ;
 357:  ! zerocal stage 2: ;
 358:  ! pose 22 of 43, ;
 359:  ! captured from below, ;
 360:  ! then from above ;
 361:J P[96] 10% FINE ;
 362:J P[97] 10% FINE ;
 363:  WAIT   3.10(sec) ;
 364:J P[98] 10% FINE ;
 365:J P[99] 10% FINE ;
 366:  WAIT   3.10(sec) ;
 367:  ! zerocal stage 2: ;
 368:  ! pose 23 of 43, ;
 369:  ! captured from below, ;
 370:  ! then from above ;
 371:J P[100] 10% FINE ;
 372:J P[101] 10% FINE ;
 373:  WAIT   3.10(sec) ;
 374:J P[102] 10% FINE ;
 375:J P[103] 10% FINE ;
 376:  WAIT   3.10(sec) ;
 377:  ! zerocal stage 2: ;
 378:  ! pose 24 of 43, ;
 379:  ! captured from below, ;
 380:  ! then from above ;
 381:J P[104] 10% FINE ;
 382:J P[105] 10% FINE ;
 383:  WAIT   3.10(sec) ;
 384:J P[106] 10% FINE ;
 385:J P[107] 10% FINE ;
 386:  WAIT   3.10(sec) ;
 387:  ! zerocal stage 2: ;
 388:  ! pose 25 of 43, ;
 389:  ! captured from below, ;
 390:  ! then from above ;
 391:J P[108] 10% FINE ;
 392:J P[109] 10% FINE ;
 393:  WAIT   3.10(sec) ;
 394:J P[110] 10% FINE ;
 395:J P[111] 10% FINE ;
 396:  WAIT   3.10(sec) ;
 397:  ! zerocal stage 2: ;
 398:  ! pose 26 of 43, ;
 399:  ! captured from below, ;
 400:  ! then from above ;
 401:J P[112] 10% FINE ;
 402:J P[113] 10% FINE ;
 403:  WAIT   3.10(sec) ;
 404:J P[114] 10% FINE ;
 405:J P[115] 10% FINE ;
 406:  WAIT   3.10(sec) ;
 407:  ! zerocal stage 2: ;
 408:  ! pose 27 of 43, ;
 409:  ! captured from below, ;
 410:  ! then from above ;
 411:J P[116] 10% FINE ;
 412:J P[117] 10% FINE ;
 413:  WAIT   3.10(sec) ;
 414:J P[118] 10% FINE ;
 415:J P[119] 10% FINE ;
 416:  WAIT   3.10(sec) ;
 417:  ! zerocal stage 2: ;
 418:  ! pose 28 of 43, ;
 419:  ! captured from below, ;
 420:  ! then from above ;
 421:J P[120] 10% FINE ;
 422:J P[121] 10% FINE ;
 423:  WAIT   3.10(sec) ;
 424:J P[122] 10% FINE ;
 425:J P[123] 10% FINE ;
 426:  WAIT   3.10(sec) ;
 427:  ! zerocal stage 2: ;
 428:  ! pose 29 of 43, ;
 429:  ! captured from below, ;
 430:  ! then from above ;
 431:J P[124] 10% FINE ;
 432:J P[125] 10% FINE ;
 433:  WAIT   3.10(sec) ;
 434:J P[126] 10% FINE ;
 435:J P[127] 10% FINE ;
 436:  WAIT   3.10(sec) ;
 437:  ! zerocal stage 2: ;
 438:  ! pose 30 of 43, ;
 439:  ! captured from below, ;
 440:  ! then from above ;
 441:J P[128] 10% FINE ;
 442:J P[129] 10% FINE ;
 443:  WAIT   3.10(sec) ;
 444:J P[130] 10% FINE ;
 445:J P[131] 10% FINE ;
 446:  WAIT   3.10(sec) ;
 447:  ! zerocal stage 2: ;
 448:  ! pose 31 of 43, ;
 449:  ! captured from below, ;
 450:  ! then from above ;
 451:J P[132] 10% FINE ;
 452:J P[133] 10% FINE ;
 453:  WAIT   3.10(sec) ;
 454:J P[134] 10% FINE ;
 455:J P[135] 10% FINE ;
 456:  WAIT   3.10(sec) ;
 457:  ! zerocal stage 2: ;
 458:  ! pose 32 of 43, ;
 459:  ! captured from below, ;
 460:  ! then from above ;
 461:J P[136] 10% FINE ;
 462:J P[137] 10% FINE ;
 463:  WAIT   3.10(sec) ;
 464:J P[138] 10% FINE ;
 465:J P[139] 10% FINE ;
 466:  WAIT   3.10(sec) ;
 467:  ! zerocal stage 2: ;
 468:  ! pose 33 of 43, ;
 469:  ! captured from below, ;
 470:  ! then from above ;
 471:J P[140] 10% FINE ;
 472:J P[141] 10% FINE ;
 473:  WAIT   3.10(sec) ;
 474:J P[142] 10% FINE ;
 475:J P[143] 10% FINE ;
 476:  WAIT   3.10(sec) ;
 477:  ! zerocal stage 2: ;
 478:  ! pose 34 of 43, ;
 479:  ! captured from below, ;
 480:  ! then from above ;
 481:J P[144] 10% FINE ;
 482:J P[145] 10% FINE ;
 483:  WAIT   3.10(sec) ;
 484:J P[146] 10% FINE ;
 485:J P[147] 10% FINE ;
 486:  WAIT   3.10(sec) ;
 487:  ! zerocal stage 2: ;
 488:  ! pose 35 of 43, ;
 489:  ! captured from below, ;
 490:  ! then from above ;
 491:J P[148] 10% FINE ;
 492:J P[149] 10% FINE ;
 493:  WAIT   3.10(sec) ;
 494:J P[150] 10% FINE ;
 495:J P[151] 10% FINE ;
 496:  WAIT   3.10(sec) ;
 497:  ! zerocal stage 2: ;
 498:  ! pose 36 of 43, ;
 499:  ! captured from below, ;
 500:  ! then from above ;
 501:J P[152] 10% FINE ;
 502:J P[153] 10% FINE ;
 503:  WAIT   3.10(sec) ;
 504:J P[154] 10% FINE ;
 505:J P[155] 10% FINE ;
 506:  WAIT   3.10(sec) ;
 507:  ! zerocal stage 2: ;
 508:  ! pose 37 of 43, ;
 509:  ! captured from below, ;
 510:  ! then from above ;
 511:J P[156] 10% FINE ;
 512:J P[157] 10% FINE ;
 513:  WAIT   3.10(sec) ;
 514:J P[158] 10% FINE ;
 515:J P[159] 10% FINE ;
 516:  WAIT   3.10(sec) ;
 517:  ! zerocal stage 2: ;
 518:  ! pose 38 of 43, ;
 519:  ! captured from below, ;
 520:  ! then from above ;
 521:J P[160] 10% FINE ;
 522:J P[161] 10% FINE ;
 523:  WAIT   3.10(sec) ;
 524:J P[162] 10% FINE ;
 525:J P[163] 10% FINE ;
 526:  WAIT   3.10(sec) ;
 527:  ! zerocal stage 2: ;
 528:  ! pose 39 of 43, ;
 529:  ! captured from below, ;
 530:  ! then from above ;
 531:J P[164] 10% FINE ;
 532:J P[165] 10% FINE ;
 533:  WAIT   3.10(sec) ;
 534:J P[166] 10% FINE ;
 535:J P[167] 10% FINE ;
 536:  WAIT   3.10(sec) ;
 537:  ! zerocal stage 2: ;
 538:  ! pose 40 of 43, ;
 539:  ! captured from below, ;
 540:  ! then from above ;
 541:J P[168] 10% FINE ;
 542:J P[169] 10% FINE ;
 543:  WAIT   3.10(sec) ;
 544:J P[170] 10% FINE ;
 545:J P[171] 10% FINE ;
 546:  WAIT   3.10(sec) ;
 547:  ! zerocal stage 2: ;
 548:  ! pose 41 of 43, ;
 549:  ! captured from below, ;
 550:  ! then from above ;
 551:J P[172] 10% FINE ;
 552:J P[173] 10% FINE ;
 553:  WAIT   3.10(sec) ;
 554:J P[174] 10% FINE ;
 555:J P[175] 10% FINE ;
 556:  WAIT   3.10(sec) ;
 557:  ! zerocal stage 2: ;
 558:  ! pose 42 of 43, ;
 559:  ! captured from below, ;
 560:  ! then from above ;
 561:J P[176] 10% FINE ;
 562:J P[177] 10% FINE ;
 563:  WAIT   3.10(sec) ;
 564:J P[178] 10% FINE ;
 565:J P[179] 10% FINE ;
 566:  WAIT   3.10(sec) ;
 567:  ! zerocal stage 2: ;
 568:  ! pose 43 of 43, ;
 569:  ! captured from below, ;
 570:  ! then from above ;
 571:J P[180] 10% FINE ;
 572:J P[181] 10% FINE ;
 573:  WAIT   3.10(sec) ;
 574:J P[182] 10% FINE ;
 575:J P[183] 10% FINE ;
 576:  WAIT   3.10(sec) ;
 577:  ! zerocal: stage 2 ;
 578:  ! done; the robot ;
 579:  ! parks where the ;
 580:  ! pendant went on the ;
 581:  ! flange (tilted past ;
 582:  ! its range) for the ;
 583:  ! closing bench ;
 584:  ! readings ;
 585:J P[184] 10% FINE ;
 586:  MESSAGE[zerocal: closing] ;
 587:  MESSAGE[bench readings: take] ;
 588:  MESSAGE[the pendant off the] ;
 589:  MESSAGE[flange to the bench] ;
 590:  MESSAGE[of stage 0 and read] ;
 591:  MESSAGE[it at 4 headings,] ;
 592:  MESSAGE[turned by hand about] ;
 593:  MESSAGE[a quarter turn on] ;
 594:  MESSAGE[the same spot] ;
 595:  MESSAGE[between them, as the] ;
 596:  MESSAGE[pendant guides. Then] ;
 597:  MESSAGE[continue.] ;
 598:  PAUSE ;
 599:  ! zerocal: session ;
 600:  ! done; the pendant ;
 601:  ! shows the result ;
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
	J1=   -90.000 deg,	J2=   -45.000 deg,	J3=     2.767 deg,
	J4=  -156.412 deg,	J5=   -41.936 deg,	J6=   154.891 deg
};
P[12]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -75.885 deg,	J3=     1.767 deg,
	J4=  -157.412 deg,	J5=     2.064 deg,	J6=   153.891 deg
};
P[13]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -74.885 deg,	J3=     2.767 deg,
	J4=  -156.412 deg,	J5=     3.064 deg,	J6=   154.891 deg
};
P[14]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -70.885 deg,	J3=     6.767 deg,
	J4=  -152.412 deg,	J5=     7.064 deg,	J6=   158.891 deg
};
P[15]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -74.885 deg,	J3=     2.767 deg,
	J4=  -156.412 deg,	J5=     3.064 deg,	J6=   154.891 deg
};
P[16]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -65.549 deg,	J3=    31.328 deg,
	J4=  -120.191 deg,	J5=  -119.980 deg,	J6=    41.685 deg
};
P[17]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -64.549 deg,	J3=    32.328 deg,
	J4=  -119.191 deg,	J5=  -118.980 deg,	J6=    42.685 deg
};
P[18]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -60.549 deg,	J3=    36.328 deg,
	J4=  -115.191 deg,	J5=  -114.980 deg,	J6=    46.685 deg
};
P[19]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -64.549 deg,	J3=    32.328 deg,
	J4=  -119.191 deg,	J5=  -118.980 deg,	J6=    42.685 deg
};
P[20]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -0.477 deg,	J3=    57.949 deg,
	J4=   -67.072 deg,	J5=   -75.878 deg,	J6=    26.398 deg
};
P[21]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.523 deg,	J3=    58.949 deg,
	J4=   -66.072 deg,	J5=   -74.878 deg,	J6=    27.398 deg
};
P[22]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.523 deg,	J3=    62.949 deg,
	J4=   -62.072 deg,	J5=   -70.878 deg,	J6=    31.398 deg
};
P[23]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.523 deg,	J3=    58.949 deg,
	J4=   -66.072 deg,	J5=   -74.878 deg,	J6=    27.398 deg
};
P[24]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -62.544 deg,	J3=   114.966 deg,
	J4=    10.497 deg,	J5=  -118.660 deg,	J6=     7.821 deg
};
P[25]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -61.544 deg,	J3=   115.966 deg,
	J4=    11.497 deg,	J5=  -117.660 deg,	J6=     8.821 deg
};
P[26]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -57.544 deg,	J3=   119.966 deg,
	J4=    15.497 deg,	J5=  -113.660 deg,	J6=    12.821 deg
};
P[27]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -61.544 deg,	J3=   115.966 deg,
	J4=    11.497 deg,	J5=  -117.660 deg,	J6=     8.821 deg
};
P[28]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -31.870 deg,	J3=   130.844 deg,
	J4=    26.210 deg,	J5=  -134.174 deg,	J6=    11.117 deg
};
P[29]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -30.870 deg,	J3=   131.844 deg,
	J4=    27.210 deg,	J5=  -133.174 deg,	J6=    12.117 deg
};
P[30]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -26.870 deg,	J3=   135.844 deg,
	J4=    31.210 deg,	J5=  -129.174 deg,	J6=    16.117 deg
};
P[31]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -30.870 deg,	J3=   131.844 deg,
	J4=    27.210 deg,	J5=  -133.174 deg,	J6=    12.117 deg
};
P[32]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -5.875 deg,	J3=   146.414 deg,
	J4=   -37.885 deg,	J5=  -137.011 deg,	J6=   -31.865 deg
};
P[33]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    -4.875 deg,	J3=   147.414 deg,
	J4=   -36.885 deg,	J5=  -136.011 deg,	J6=   -30.865 deg
};
P[34]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    -0.875 deg,	J3=   151.414 deg,
	J4=   -32.885 deg,	J5=  -132.011 deg,	J6=   -26.865 deg
};
P[35]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    -4.875 deg,	J3=   147.414 deg,
	J4=   -36.885 deg,	J5=  -136.011 deg,	J6=   -30.865 deg
};
P[36]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -33.996 deg,	J3=   104.916 deg,
	J4=  -155.761 deg,	J5=   -82.176 deg,	J6=   -13.142 deg
};
P[37]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -32.996 deg,	J3=   105.916 deg,
	J4=  -154.761 deg,	J5=   -81.176 deg,	J6=   -12.142 deg
};
P[38]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -28.996 deg,	J3=   109.916 deg,
	J4=  -150.761 deg,	J5=   -77.176 deg,	J6=    -8.142 deg
};
P[39]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -32.996 deg,	J3=   105.916 deg,
	J4=  -154.761 deg,	J5=   -81.176 deg,	J6=   -12.142 deg
};
P[40]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -75.889 deg,	J3=   104.729 deg,
	J4=  -164.574 deg,	J5=   -71.753 deg,	J6=    -6.276 deg
};
P[41]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -74.889 deg,	J3=   105.729 deg,
	J4=  -163.574 deg,	J5=   -70.753 deg,	J6=    -5.276 deg
};
P[42]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -70.889 deg,	J3=   109.729 deg,
	J4=  -159.574 deg,	J5=   -66.753 deg,	J6=    -1.276 deg
};
P[43]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -74.889 deg,	J3=   105.729 deg,
	J4=  -163.574 deg,	J5=   -70.753 deg,	J6=    -5.276 deg
};
P[44]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -66.633 deg,	J3=   144.980 deg,
	J4=  -167.611 deg,	J5=   -37.725 deg,	J6=    -7.568 deg
};
P[45]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -65.633 deg,	J3=   145.980 deg,
	J4=  -166.611 deg,	J5=   -36.725 deg,	J6=    -6.568 deg
};
P[46]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -61.633 deg,	J3=   149.980 deg,
	J4=  -162.611 deg,	J5=   -32.725 deg,	J6=    -2.568 deg
};
P[47]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -65.633 deg,	J3=   145.980 deg,
	J4=  -166.611 deg,	J5=   -36.725 deg,	J6=    -6.568 deg
};
P[48]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -63.690 deg,	J3=   177.374 deg,
	J4=  -113.053 deg,	J5=    -4.526 deg,	J6=   -69.108 deg
};
P[49]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -62.690 deg,	J3=   178.374 deg,
	J4=  -112.053 deg,	J5=    -3.526 deg,	J6=   -68.108 deg
};
P[50]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -58.690 deg,	J3=   182.374 deg,
	J4=  -108.053 deg,	J5=     0.474 deg,	J6=   -64.108 deg
};
P[51]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -62.690 deg,	J3=   178.374 deg,
	J4=  -112.053 deg,	J5=    -3.526 deg,	J6=   -68.108 deg
};
P[52]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -31.108 deg,	J3=   184.676 deg,
	J4=  -157.142 deg,	J5=    11.103 deg,	J6=   -24.493 deg
};
P[53]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -30.108 deg,	J3=   185.676 deg,
	J4=  -156.142 deg,	J5=    12.103 deg,	J6=   -23.493 deg
};
P[54]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -26.108 deg,	J3=   189.676 deg,
	J4=  -152.142 deg,	J5=    16.103 deg,	J6=   -19.493 deg
};
P[55]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -30.108 deg,	J3=   185.676 deg,
	J4=  -156.142 deg,	J5=    12.103 deg,	J6=   -23.493 deg
};
P[56]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -32.835 deg,	J3=   136.200 deg,
	J4=  -145.007 deg,	J5=   125.949 deg,	J6=  -153.792 deg
};
P[57]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -31.835 deg,	J3=   137.200 deg,
	J4=  -144.007 deg,	J5=   126.949 deg,	J6=  -152.792 deg
};
P[58]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -27.835 deg,	J3=   141.200 deg,
	J4=  -140.007 deg,	J5=   130.949 deg,	J6=  -148.792 deg
};
P[59]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -31.835 deg,	J3=   137.200 deg,
	J4=  -144.007 deg,	J5=   126.949 deg,	J6=  -152.792 deg
};
P[60]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -75.702 deg,	J3=   159.383 deg,
	J4=    77.695 deg,	J5=    47.882 deg,	J6=   115.828 deg
};
P[61]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -74.702 deg,	J3=   160.383 deg,
	J4=    78.695 deg,	J5=    48.882 deg,	J6=   116.828 deg
};
P[62]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -70.702 deg,	J3=   164.383 deg,
	J4=    82.695 deg,	J5=    52.882 deg,	J6=   120.828 deg
};
P[63]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -74.702 deg,	J3=   160.383 deg,
	J4=    78.695 deg,	J5=    48.882 deg,	J6=   116.828 deg
};
P[64]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -5.214 deg,	J3=   152.490 deg,
	J4=   124.195 deg,	J5=   -39.833 deg,	J6=    47.493 deg
};
P[65]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    -4.214 deg,	J3=   153.490 deg,
	J4=   125.195 deg,	J5=   -38.833 deg,	J6=    48.493 deg
};
P[66]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    -0.214 deg,	J3=   157.490 deg,
	J4=   129.195 deg,	J5=   -34.833 deg,	J6=    52.493 deg
};
P[67]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    -4.214 deg,	J3=   153.490 deg,
	J4=   125.195 deg,	J5=   -38.833 deg,	J6=    48.493 deg
};
P[68]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    61.151 deg,	J3=   102.154 deg,
	J4=   147.102 deg,	J5=   104.895 deg,	J6=   174.262 deg
};
P[69]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    62.151 deg,	J3=   103.154 deg,
	J4=   148.102 deg,	J5=   105.895 deg,	J6=   175.262 deg
};
P[70]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    66.151 deg,	J3=   107.154 deg,
	J4=   152.102 deg,	J5=   109.895 deg,	J6=   179.262 deg
};
P[71]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    62.151 deg,	J3=   103.154 deg,
	J4=   148.102 deg,	J5=   105.895 deg,	J6=   175.262 deg
};
P[72]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    73.584 deg,	J3=    97.974 deg,
	J4=   -55.853 deg,	J5=  -100.936 deg,	J6=   -12.029 deg
};
P[73]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    74.584 deg,	J3=    98.974 deg,
	J4=   -54.853 deg,	J5=   -99.936 deg,	J6=   -11.029 deg
};
P[74]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    78.584 deg,	J3=   102.974 deg,
	J4=   -50.853 deg,	J5=   -95.936 deg,	J6=    -7.029 deg
};
P[75]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    74.584 deg,	J3=    98.974 deg,
	J4=   -54.853 deg,	J5=   -99.936 deg,	J6=   -11.029 deg
};
P[76]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    73.791 deg,	J3=    29.671 deg,
	J4=    82.688 deg,	J5=   -91.617 deg,	J6=   -54.543 deg
};
P[77]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    74.791 deg,	J3=    30.671 deg,
	J4=    83.688 deg,	J5=   -90.617 deg,	J6=   -53.543 deg
};
P[78]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    78.791 deg,	J3=    34.671 deg,
	J4=    87.688 deg,	J5=   -86.617 deg,	J6=   -49.543 deg
};
P[79]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    74.791 deg,	J3=    30.671 deg,
	J4=    83.688 deg,	J5=   -90.617 deg,	J6=   -53.543 deg
};
P[80]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    61.663 deg,	J3=   -31.904 deg,
	J4=   163.172 deg,	J5=   -28.709 deg,	J6=  -169.031 deg
};
P[81]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    62.663 deg,	J3=   -30.904 deg,
	J4=   164.172 deg,	J5=   -27.709 deg,	J6=  -168.031 deg
};
P[82]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    66.663 deg,	J3=   -26.904 deg,
	J4=   168.172 deg,	J5=   -23.709 deg,	J6=  -164.031 deg
};
P[83]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    62.663 deg,	J3=   -30.904 deg,
	J4=   164.172 deg,	J5=   -27.709 deg,	J6=  -168.031 deg
};
P[84]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    59.794 deg,	J3=    -1.699 deg,
	J4=   119.930 deg,	J5=     5.037 deg,	J6=  -120.309 deg
};
P[85]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    60.794 deg,	J3=    -0.699 deg,
	J4=   120.930 deg,	J5=     6.037 deg,	J6=  -119.309 deg
};
P[86]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    64.794 deg,	J3=     3.301 deg,
	J4=   124.930 deg,	J5=    10.037 deg,	J6=  -115.309 deg
};
P[87]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    60.794 deg,	J3=    -0.699 deg,
	J4=   120.930 deg,	J5=     6.037 deg,	J6=  -119.309 deg
};
P[88]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    60.539 deg,	J3=    12.934 deg,
	J4=   143.144 deg,	J5=    18.744 deg,	J6=  -144.875 deg
};
P[89]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    61.539 deg,	J3=    13.934 deg,
	J4=   144.144 deg,	J5=    19.744 deg,	J6=  -143.875 deg
};
P[90]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    65.539 deg,	J3=    17.934 deg,
	J4=   148.144 deg,	J5=    23.744 deg,	J6=  -139.875 deg
};
P[91]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    61.539 deg,	J3=    13.934 deg,
	J4=   144.144 deg,	J5=    19.744 deg,	J6=  -143.875 deg
};
P[92]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -75.885 deg,	J3=     1.767 deg,
	J4=  -157.412 deg,	J5=     2.064 deg,	J6=   153.891 deg
};
P[93]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -74.885 deg,	J3=     2.767 deg,
	J4=  -156.412 deg,	J5=     3.064 deg,	J6=   154.891 deg
};
P[94]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -70.885 deg,	J3=     6.767 deg,
	J4=  -152.412 deg,	J5=     7.064 deg,	J6=   158.891 deg
};
P[95]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -74.885 deg,	J3=     2.767 deg,
	J4=  -156.412 deg,	J5=     3.064 deg,	J6=   154.891 deg
};
P[96]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    35.542 deg,	J3=    19.898 deg,
	J4=    71.902 deg,	J5=   115.732 deg,	J6=  -114.509 deg
};
P[97]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    36.542 deg,	J3=    20.898 deg,
	J4=    72.902 deg,	J5=   116.732 deg,	J6=  -113.509 deg
};
P[98]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    40.542 deg,	J3=    24.898 deg,
	J4=    76.902 deg,	J5=   120.732 deg,	J6=  -109.509 deg
};
P[99]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    36.542 deg,	J3=    20.898 deg,
	J4=    72.902 deg,	J5=   116.732 deg,	J6=  -113.509 deg
};
P[100]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=     5.414 deg,	J3=   -41.505 deg,
	J4=   119.194 deg,	J5=   121.182 deg,	J6=   -43.990 deg
};
P[101]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     6.414 deg,	J3=   -40.505 deg,
	J4=   120.194 deg,	J5=   122.182 deg,	J6=   -42.990 deg
};
P[102]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    10.414 deg,	J3=   -36.505 deg,
	J4=   124.194 deg,	J5=   126.182 deg,	J6=   -38.990 deg
};
P[103]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     6.414 deg,	J3=   -40.505 deg,
	J4=   120.194 deg,	J5=   122.182 deg,	J6=   -42.990 deg
};
P[104]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -64.341 deg,	J3=    10.831 deg,
	J4=   114.517 deg,	J5=    19.584 deg,	J6=  -118.523 deg
};
P[105]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -63.341 deg,	J3=    11.831 deg,
	J4=   115.517 deg,	J5=    20.584 deg,	J6=  -117.523 deg
};
P[106]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -59.341 deg,	J3=    15.831 deg,
	J4=   119.517 deg,	J5=    24.584 deg,	J6=  -113.523 deg
};
P[107]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -63.341 deg,	J3=    11.831 deg,
	J4=   115.517 deg,	J5=    20.584 deg,	J6=  -117.523 deg
};
P[108]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -75.788 deg,	J3=     7.937 deg,
	J4=   136.710 deg,	J5=     4.882 deg,	J6=  -135.996 deg
};
P[109]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -74.788 deg,	J3=     8.937 deg,
	J4=   137.710 deg,	J5=     5.882 deg,	J6=  -134.996 deg
};
P[110]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -70.788 deg,	J3=    12.937 deg,
	J4=   141.710 deg,	J5=     9.882 deg,	J6=  -130.996 deg
};
P[111]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -74.788 deg,	J3=     8.937 deg,
	J4=   137.710 deg,	J5=     5.882 deg,	J6=  -134.996 deg
};
P[112]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -75.521 deg,	J3=    11.539 deg,
	J4=   118.703 deg,	J5=    33.359 deg,	J6=  -117.346 deg
};
P[113]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -74.521 deg,	J3=    12.539 deg,
	J4=   119.703 deg,	J5=    34.359 deg,	J6=  -116.346 deg
};
P[114]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -70.521 deg,	J3=    16.539 deg,
	J4=   123.703 deg,	J5=    38.359 deg,	J6=  -112.346 deg
};
P[115]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -74.521 deg,	J3=    12.539 deg,
	J4=   119.703 deg,	J5=    34.359 deg,	J6=  -116.346 deg
};
P[116]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -63.674 deg,	J3=   -17.136 deg,
	J4=    56.140 deg,	J5=    18.128 deg,	J6=   -54.090 deg
};
P[117]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -62.674 deg,	J3=   -16.136 deg,
	J4=    57.140 deg,	J5=    19.128 deg,	J6=   -53.090 deg
};
P[118]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -58.674 deg,	J3=   -12.136 deg,
	J4=    61.140 deg,	J5=    23.128 deg,	J6=   -49.090 deg
};
P[119]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -62.674 deg,	J3=   -16.136 deg,
	J4=    57.140 deg,	J5=    19.128 deg,	J6=   -53.090 deg
};
P[120]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=     6.029 deg,	J3=   -37.124 deg,
	J4=   -48.051 deg,	J5=  -134.195 deg,	J6=   143.544 deg
};
P[121]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     7.029 deg,	J3=   -36.124 deg,
	J4=   -47.051 deg,	J5=  -133.195 deg,	J6=   144.544 deg
};
P[122]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    11.029 deg,	J3=   -32.124 deg,
	J4=   -43.051 deg,	J5=  -129.195 deg,	J6=   148.544 deg
};
P[123]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     7.029 deg,	J3=   -36.124 deg,
	J4=   -47.051 deg,	J5=  -133.195 deg,	J6=   144.544 deg
};
P[124]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=     5.465 deg,	J3=    -4.340 deg,
	J4=  -102.288 deg,	J5=   -13.626 deg,	J6=    96.691 deg
};
P[125]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     6.465 deg,	J3=    -3.340 deg,
	J4=  -101.288 deg,	J5=   -12.626 deg,	J6=    97.691 deg
};
P[126]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    10.465 deg,	J3=     0.660 deg,
	J4=   -97.288 deg,	J5=    -8.626 deg,	J6=   101.691 deg
};
P[127]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     6.465 deg,	J3=    -3.340 deg,
	J4=  -101.288 deg,	J5=   -12.626 deg,	J6=    97.691 deg
};
P[128]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    34.809 deg,	J3=   -14.886 deg,
	J4=  -142.416 deg,	J5=   -17.126 deg,	J6=   135.967 deg
};
P[129]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    35.809 deg,	J3=   -13.886 deg,
	J4=  -141.416 deg,	J5=   -16.126 deg,	J6=   136.967 deg
};
P[130]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    39.809 deg,	J3=    -9.886 deg,
	J4=  -137.416 deg,	J5=   -12.126 deg,	J6=   140.967 deg
};
P[131]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    35.809 deg,	J3=   -13.886 deg,
	J4=  -141.416 deg,	J5=   -16.126 deg,	J6=   136.967 deg
};
P[132]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    61.880 deg,	J3=    17.074 deg,
	J4=  -172.242 deg,	J5=    21.746 deg,	J6=   175.793 deg
};
P[133]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    62.880 deg,	J3=    18.074 deg,
	J4=  -171.242 deg,	J5=    22.746 deg,	J6=   176.793 deg
};
P[134]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    66.880 deg,	J3=    22.074 deg,
	J4=  -167.242 deg,	J5=    26.746 deg,	J6=   180.793 deg
};
P[135]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    62.880 deg,	J3=    18.074 deg,
	J4=  -171.242 deg,	J5=    22.746 deg,	J6=   176.793 deg
};
P[136]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    72.910 deg,	J3=    -6.022 deg,
	J4=   -96.981 deg,	J5=   -20.064 deg,	J6=    97.598 deg
};
P[137]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    73.910 deg,	J3=    -5.022 deg,
	J4=   -95.981 deg,	J5=   -19.064 deg,	J6=    98.598 deg
};
P[138]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    77.910 deg,	J3=    -1.022 deg,
	J4=   -91.981 deg,	J5=   -15.064 deg,	J6=   102.598 deg
};
P[139]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    73.910 deg,	J3=    -5.022 deg,
	J4=   -95.981 deg,	J5=   -19.064 deg,	J6=    98.598 deg
};
P[140]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    73.671 deg,	J3=    14.236 deg,
	J4=   -42.633 deg,	J5=   -23.520 deg,	J6=    38.517 deg
};
P[141]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    74.671 deg,	J3=    15.236 deg,
	J4=   -41.633 deg,	J5=   -22.520 deg,	J6=    39.517 deg
};
P[142]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    78.671 deg,	J3=    19.236 deg,
	J4=   -37.633 deg,	J5=   -18.520 deg,	J6=    43.517 deg
};
P[143]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    74.671 deg,	J3=    15.236 deg,
	J4=   -41.633 deg,	J5=   -22.520 deg,	J6=    39.517 deg
};
P[144]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    60.295 deg,	J3=    10.639 deg,
	J4=   -39.765 deg,	J5=   -20.561 deg,	J6=    37.382 deg
};
P[145]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    61.295 deg,	J3=    11.639 deg,
	J4=   -38.765 deg,	J5=   -19.561 deg,	J6=    38.382 deg
};
P[146]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    65.295 deg,	J3=    15.639 deg,
	J4=   -34.765 deg,	J5=   -15.561 deg,	J6=    42.382 deg
};
P[147]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    61.295 deg,	J3=    11.639 deg,
	J4=   -38.765 deg,	J5=   -19.561 deg,	J6=    38.382 deg
};
P[148]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    29.623 deg,	J3=   -16.923 deg,
	J4=    23.119 deg,	J5=    11.960 deg,	J6=   -25.729 deg
};
P[149]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    30.623 deg,	J3=   -15.923 deg,
	J4=    24.119 deg,	J5=    12.960 deg,	J6=   -24.729 deg
};
P[150]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    34.623 deg,	J3=   -11.923 deg,
	J4=    28.119 deg,	J5=    16.960 deg,	J6=   -20.729 deg
};
P[151]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    30.623 deg,	J3=   -15.923 deg,
	J4=    24.119 deg,	J5=    12.960 deg,	J6=   -24.729 deg
};
P[152]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    61.085 deg,	J3=   -32.183 deg,
	J4=    38.722 deg,	J5=    34.160 deg,	J6=   -35.357 deg
};
P[153]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    62.085 deg,	J3=   -31.183 deg,
	J4=    39.722 deg,	J5=    35.160 deg,	J6=   -34.357 deg
};
P[154]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    66.085 deg,	J3=   -27.183 deg,
	J4=    43.722 deg,	J5=    39.160 deg,	J6=   -30.357 deg
};
P[155]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    62.085 deg,	J3=   -31.183 deg,
	J4=    39.722 deg,	J5=    35.160 deg,	J6=   -34.357 deg
};
P[156]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    30.383 deg,	J3=    -5.758 deg,
	J4=    63.012 deg,	J5=    -2.710 deg,	J6=   -59.518 deg
};
P[157]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    31.383 deg,	J3=    -4.758 deg,
	J4=    64.012 deg,	J5=    -1.710 deg,	J6=   -58.518 deg
};
P[158]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    35.383 deg,	J3=    -0.758 deg,
	J4=    68.012 deg,	J5=     2.290 deg,	J6=   -54.518 deg
};
P[159]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    31.383 deg,	J3=    -4.758 deg,
	J4=    64.012 deg,	J5=    -1.710 deg,	J6=   -58.518 deg
};
P[160]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    36.216 deg,	J3=   -58.829 deg,
	J4=     6.274 deg,	J5=  -125.709 deg,	J6=  -181.524 deg
};
P[161]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    37.216 deg,	J3=   -57.829 deg,
	J4=     7.274 deg,	J5=  -124.709 deg,	J6=  -180.524 deg
};
P[162]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    41.216 deg,	J3=   -53.829 deg,
	J4=    11.274 deg,	J5=  -120.709 deg,	J6=  -176.524 deg
};
P[163]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    37.216 deg,	J3=   -57.829 deg,
	J4=     7.274 deg,	J5=  -124.709 deg,	J6=  -180.524 deg
};
P[164]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=     8.341 deg,	J3=  -148.304 deg,
	J4=   -69.510 deg,	J5=   122.340 deg,	J6=   -49.310 deg
};
P[165]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     9.341 deg,	J3=  -147.304 deg,
	J4=   -68.510 deg,	J5=   123.340 deg,	J6=   -48.310 deg
};
P[166]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    13.341 deg,	J3=  -143.304 deg,
	J4=   -64.510 deg,	J5=   127.340 deg,	J6=   -44.310 deg
};
P[167]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     9.341 deg,	J3=  -147.304 deg,
	J4=   -68.510 deg,	J5=   123.340 deg,	J6=   -48.310 deg
};
P[168]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    59.242 deg,	J3=  -183.160 deg,
	J4=    17.248 deg,	J5=    -3.415 deg,	J6=   166.526 deg
};
P[169]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    60.242 deg,	J3=  -182.160 deg,
	J4=    18.248 deg,	J5=    -2.415 deg,	J6=   167.526 deg
};
P[170]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    64.242 deg,	J3=  -178.160 deg,
	J4=    22.248 deg,	J5=     1.585 deg,	J6=   171.526 deg
};
P[171]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    60.242 deg,	J3=  -182.160 deg,
	J4=    18.248 deg,	J5=    -2.415 deg,	J6=   167.526 deg
};
P[172]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    73.274 deg,	J3=  -211.087 deg,
	J4=   -64.041 deg,	J5=  -132.115 deg,	J6=   -51.949 deg
};
P[173]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    74.274 deg,	J3=  -210.087 deg,
	J4=   -63.041 deg,	J5=  -131.115 deg,	J6=   -50.949 deg
};
P[174]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    78.274 deg,	J3=  -206.087 deg,
	J4=   -59.041 deg,	J5=  -127.115 deg,	J6=   -46.949 deg
};
P[175]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    74.274 deg,	J3=  -210.087 deg,
	J4=   -63.041 deg,	J5=  -131.115 deg,	J6=   -50.949 deg
};
P[176]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -75.885 deg,	J3=     1.767 deg,
	J4=  -157.412 deg,	J5=     2.064 deg,	J6=   153.891 deg
};
P[177]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -74.885 deg,	J3=     2.767 deg,
	J4=  -156.412 deg,	J5=     3.064 deg,	J6=   154.891 deg
};
P[178]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -70.885 deg,	J3=     6.767 deg,
	J4=  -152.412 deg,	J5=     7.064 deg,	J6=   158.891 deg
};
P[179]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -74.885 deg,	J3=     2.767 deg,
	J4=  -156.412 deg,	J5=     3.064 deg,	J6=   154.891 deg
};
P[180]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    35.542 deg,	J3=    19.898 deg,
	J4=    71.902 deg,	J5=   115.732 deg,	J6=  -114.509 deg
};
P[181]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    36.542 deg,	J3=    20.898 deg,
	J4=    72.902 deg,	J5=   116.732 deg,	J6=  -113.509 deg
};
P[182]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    40.542 deg,	J3=    24.898 deg,
	J4=    76.902 deg,	J5=   120.732 deg,	J6=  -109.509 deg
};
P[183]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    36.542 deg,	J3=    20.898 deg,
	J4=    72.902 deg,	J5=   116.732 deg,	J6=  -113.509 deg
};
P[184]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -45.000 deg,	J3=     2.767 deg,
	J4=  -156.412 deg,	J5=   -41.936 deg,	J6=   154.891 deg
};
/END
