/PROG  ZC_M20IA
/ATTR
OWNER		= MNEDITOR;
COMMENT		= "zerocal";
PROG_SIZE	= 0;
CREATE		= DATE 23-11-14  TIME 22:13:20;
MODIFIED	= DATE 23-11-14  TIME 22:13:20;
FILE_NAME	= ;
VERSION		= 0;
LINE_COUNT	= 608;
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
  55:  ! and continue: the ;
  56:  ! program ends there ;
  57:  ! and the robot is ;
  58:  ! free. Then read the ;
  59:  ! pendant on the bench ;
  60:  ! as in stage 0 (4 ;
  61:  ! headings, turned by ;
  62:  ! hand about a quarter ;
  63:  ! turn on the same ;
  64:  ! spot between them). ;
  65:  ! Speed: joint moves ;
  66:  ! at 10 % of each ;
  67:  ! joint's maximum ;
  68:  ! speed, exact stops. ;
  69:  ! Dwell 3.1 s at each ;
  70:  ! capture: settling 1 ;
  71:  ! s (stated default) + ;
  72:  ! the pendant's 2 s ;
  73:  ! still window + 2 ;
  74:  ! sensor periods of ;
  75:  ! 0.05 s. ;
  76:  ! Predicted robot time ;
  77:  ! 11.7 min, until the ;
  78:  ! pendant is off the ;
  79:  ! flange: motion 232 ;
  80:  ! s, dwell 279 s (90 ;
  81:  ! captures), 3 ;
  82:  ! mountings 180 s, ;
  83:  ! operator OKs 10 s; ;
  84:  ! then the closing ;
  85:  ! bench readings, 42 ;
  86:  ! s, the robot free. ;
  87:  ! WARNING: the path is ;
  88:  ! NOT checked for ;
  89:  ! collisions with the ;
  90:  ! cell, the pendant or ;
  91:  ! its bracket. Check ;
  92:  ! the cell, then step ;
  93:  ! through the program ;
  94:  ! once at reduced ;
  95:  ! speed (T1) before ;
  96:  ! running it. ;
  97:  ! zerocal stage 1: the ;
  98:  ! pendant goes on the ;
  99:  ! upper arm here, ;
 100:  ! tilted past its ;
 101:  ! range so that it ;
 102:  ! cannot capture yet ;
 103:J P[1] 10% FINE ;
 104:  MESSAGE[zerocal: clip the] ;
 105:  MESSAGE[pendant to the upper] ;
 106:  MESSAGE[arm (its screen at] ;
 107:  MESSAGE[STAGE 1), then] ;
 108:  MESSAGE[continue.] ;
 109:  PAUSE ;
 110:  ! zerocal stage 1: the ;
 111:  ! stage-1 pose, ;
 112:  ! captured from below, ;
 113:  ! then from above ;
 114:J P[2] 10% FINE ;
 115:J P[3] 10% FINE ;
 116:  WAIT   3.10(sec) ;
 117:J P[4] 10% FINE ;
 118:J P[5] 10% FINE ;
 119:  WAIT   3.10(sec) ;
 120:  ! zerocal stage 1: ;
 121:  ! joint 1 turned by ;
 122:  ! 180 deg, captured ;
 123:  ! from below, then ;
 124:  ! from above ;
 125:J P[6] 10% FINE ;
 126:J P[7] 10% FINE ;
 127:J P[8] 10% FINE ;
 128:  MESSAGE[zerocal: press OK on] ;
 129:  MESSAGE[the pendant (after] ;
 130:  MESSAGE[the half turn only] ;
 131:  MESSAGE[OK arms it), then] ;
 132:  MESSAGE[continue.] ;
 133:  PAUSE ;
 134:  WAIT   3.10(sec) ;
 135:J P[9] 10% FINE ;
 136:J P[10] 10% FINE ;
 137:  WAIT   3.10(sec) ;
 138:  ! zerocal: joint 1 ;
 139:  ! back; the pendant ;
 140:  ! goes from the upper ;
 141:  ! arm to the flange ;
 142:  ! here, both tilted ;
 143:  ! past its range ;
 144:J P[11] 10% FINE ;
 145:  MESSAGE[zerocal: move the] ;
 146:  MESSAGE[pendant from the] ;
 147:  MESSAGE[upper arm to the] ;
 148:  MESSAGE[flange (its screen] ;
 149:  MESSAGE[at POSE 1), then] ;
 150:  MESSAGE[continue.] ;
 151:  PAUSE ;
 152:  ! zerocal stage 2: ;
 153:  ! pose 1 of 43, ;
 154:  ! captured from below, ;
 155:  ! then from above ;
 156:J P[12] 10% FINE ;
 157:J P[13] 10% FINE ;
 158:  WAIT   3.10(sec) ;
 159:J P[14] 10% FINE ;
 160:J P[15] 10% FINE ;
 161:  WAIT   3.10(sec) ;
 162:  ! zerocal stage 2: ;
 163:  ! pose 2 of 43, ;
 164:  ! captured from below, ;
 165:  ! then from above ;
 166:J P[16] 10% FINE ;
 167:J P[17] 10% FINE ;
 168:  WAIT   3.10(sec) ;
 169:J P[18] 10% FINE ;
 170:J P[19] 10% FINE ;
 171:  WAIT   3.10(sec) ;
 172:  ! zerocal stage 2: ;
 173:  ! pose 3 of 43, ;
 174:  ! captured from below, ;
 175:  ! then from above ;
 176:J P[20] 10% FINE ;
 177:J P[21] 10% FINE ;
 178:  WAIT   3.10(sec) ;
 179:J P[22] 10% FINE ;
 180:J P[23] 10% FINE ;
 181:  WAIT   3.10(sec) ;
 182:  ! zerocal stage 2: ;
 183:  ! pose 4 of 43, ;
 184:  ! captured from below, ;
 185:  ! then from above ;
 186:J P[24] 10% FINE ;
 187:J P[25] 10% FINE ;
 188:  WAIT   3.10(sec) ;
 189:J P[26] 10% FINE ;
 190:J P[27] 10% FINE ;
 191:  WAIT   3.10(sec) ;
 192:  ! zerocal stage 2: ;
 193:  ! pose 5 of 43, ;
 194:  ! captured from below, ;
 195:  ! then from above ;
 196:J P[28] 10% FINE ;
 197:J P[29] 10% FINE ;
 198:  WAIT   3.10(sec) ;
 199:J P[30] 10% FINE ;
 200:J P[31] 10% FINE ;
 201:  WAIT   3.10(sec) ;
 202:  ! zerocal stage 2: ;
 203:  ! pose 6 of 43, ;
 204:  ! captured from below, ;
 205:  ! then from above ;
 206:J P[32] 10% FINE ;
 207:J P[33] 10% FINE ;
 208:  WAIT   3.10(sec) ;
 209:J P[34] 10% FINE ;
 210:J P[35] 10% FINE ;
 211:  WAIT   3.10(sec) ;
 212:  ! zerocal stage 2: ;
 213:  ! pose 7 of 43, ;
 214:  ! captured from below, ;
 215:  ! then from above ;
 216:J P[36] 10% FINE ;
 217:J P[37] 10% FINE ;
 218:  WAIT   3.10(sec) ;
 219:J P[38] 10% FINE ;
 220:J P[39] 10% FINE ;
 221:  WAIT   3.10(sec) ;
 222:  ! zerocal stage 2: ;
 223:  ! pose 8 of 43, ;
 224:  ! captured from below, ;
 225:  ! then from above ;
 226:J P[40] 10% FINE ;
 227:J P[41] 10% FINE ;
 228:  WAIT   3.10(sec) ;
 229:J P[42] 10% FINE ;
 230:J P[43] 10% FINE ;
 231:  WAIT   3.10(sec) ;
 232:  ! zerocal stage 2: ;
 233:  ! pose 9 of 43, ;
 234:  ! captured from below, ;
 235:  ! then from above ;
 236:J P[44] 10% FINE ;
 237:J P[45] 10% FINE ;
 238:  WAIT   3.10(sec) ;
 239:J P[46] 10% FINE ;
 240:J P[47] 10% FINE ;
 241:  WAIT   3.10(sec) ;
 242:  ! zerocal stage 2: ;
 243:  ! pose 10 of 43, ;
 244:  ! captured from below, ;
 245:  ! then from above ;
 246:J P[48] 10% FINE ;
 247:J P[49] 10% FINE ;
 248:  WAIT   3.10(sec) ;
 249:J P[50] 10% FINE ;
 250:J P[51] 10% FINE ;
 251:  WAIT   3.10(sec) ;
 252:  ! zerocal stage 2: ;
 253:  ! pose 11 of 43, ;
 254:  ! captured from below, ;
 255:  ! then from above ;
 256:J P[52] 10% FINE ;
 257:J P[53] 10% FINE ;
 258:  WAIT   3.10(sec) ;
 259:J P[54] 10% FINE ;
 260:J P[55] 10% FINE ;
 261:  WAIT   3.10(sec) ;
 262:  ! zerocal stage 2: ;
 263:  ! pose 12 of 43, ;
 264:  ! captured from below, ;
 265:  ! then from above ;
 266:J P[56] 10% FINE ;
 267:J P[57] 10% FINE ;
 268:  WAIT   3.10(sec) ;
 269:J P[58] 10% FINE ;
 270:J P[59] 10% FINE ;
 271:  WAIT   3.10(sec) ;
 272:  ! zerocal stage 2: ;
 273:  ! pose 13 of 43, ;
 274:  ! captured from below, ;
 275:  ! then from above ;
 276:J P[60] 10% FINE ;
 277:J P[61] 10% FINE ;
 278:  WAIT   3.10(sec) ;
 279:J P[62] 10% FINE ;
 280:J P[63] 10% FINE ;
 281:  WAIT   3.10(sec) ;
 282:  ! zerocal stage 2: ;
 283:  ! pose 14 of 43, ;
 284:  ! captured from below, ;
 285:  ! then from above ;
 286:J P[64] 10% FINE ;
 287:J P[65] 10% FINE ;
 288:  WAIT   3.10(sec) ;
 289:J P[66] 10% FINE ;
 290:J P[67] 10% FINE ;
 291:  WAIT   3.10(sec) ;
 292:  ! zerocal stage 2: ;
 293:  ! pose 15 of 43, ;
 294:  ! captured from below, ;
 295:  ! then from above ;
 296:J P[68] 10% FINE ;
 297:J P[69] 10% FINE ;
 298:  WAIT   3.10(sec) ;
 299:J P[70] 10% FINE ;
 300:J P[71] 10% FINE ;
 301:  WAIT   3.10(sec) ;
 302:  ! zerocal stage 2: ;
 303:  ! pose 16 of 43, ;
 304:  ! captured from below, ;
 305:  ! then from above ;
 306:J P[72] 10% FINE ;
 307:J P[73] 10% FINE ;
 308:  WAIT   3.10(sec) ;
 309:J P[74] 10% FINE ;
 310:J P[75] 10% FINE ;
 311:  WAIT   3.10(sec) ;
 312:  ! zerocal stage 2: ;
 313:  ! pose 17 of 43, ;
 314:  ! captured from below, ;
 315:  ! then from above ;
 316:J P[76] 10% FINE ;
 317:J P[77] 10% FINE ;
 318:  WAIT   3.10(sec) ;
 319:J P[78] 10% FINE ;
 320:J P[79] 10% FINE ;
 321:  WAIT   3.10(sec) ;
 322:  ! zerocal stage 2: ;
 323:  ! pose 18 of 43, ;
 324:  ! captured from below, ;
 325:  ! then from above ;
 326:J P[80] 10% FINE ;
 327:J P[81] 10% FINE ;
 328:  WAIT   3.10(sec) ;
 329:J P[82] 10% FINE ;
 330:J P[83] 10% FINE ;
 331:  WAIT   3.10(sec) ;
 332:  ! zerocal stage 2: ;
 333:  ! pose 19 of 43, ;
 334:  ! captured from below, ;
 335:  ! then from above ;
 336:J P[84] 10% FINE ;
 337:J P[85] 10% FINE ;
 338:  WAIT   3.10(sec) ;
 339:J P[86] 10% FINE ;
 340:J P[87] 10% FINE ;
 341:  WAIT   3.10(sec) ;
 342:  ! zerocal stage 2: ;
 343:  ! pose 20 of 43, ;
 344:  ! captured from below, ;
 345:  ! then from above ;
 346:J P[88] 10% FINE ;
 347:J P[89] 10% FINE ;
 348:  WAIT   3.10(sec) ;
 349:J P[90] 10% FINE ;
 350:J P[91] 10% FINE ;
 351:  WAIT   3.10(sec) ;
 352:  ! zerocal stage 2: ;
 353:  ! pose 21 of 43, ;
 354:  ! captured from below, ;
 355:  ! then from above ;
 356:J P[92] 10% FINE ;
 357:J P[93] 10% FINE ;
 358:  WAIT   3.10(sec) ;
 359:J P[94] 10% FINE ;
 360:J P[95] 10% FINE ;
 361:  WAIT   3.10(sec) ;
 362:  ! zerocal stage 2: ;
 363:  ! pose 22 of 43, ;
 364:  ! captured from below, ;
 365:  ! then from above ;
 366:J P[96] 10% FINE ;
 367:J P[97] 10% FINE ;
 368:  WAIT   3.10(sec) ;
 369:J P[98] 10% FINE ;
 370:J P[99] 10% FINE ;
 371:  WAIT   3.10(sec) ;
 372:  ! zerocal stage 2: ;
 373:  ! pose 23 of 43, ;
 374:  ! captured from below, ;
 375:  ! then from above ;
 376:J P[100] 10% FINE ;
 377:J P[101] 10% FINE ;
 378:  WAIT   3.10(sec) ;
 379:J P[102] 10% FINE ;
 380:J P[103] 10% FINE ;
 381:  WAIT   3.10(sec) ;
 382:  ! zerocal stage 2: ;
 383:  ! pose 24 of 43, ;
 384:  ! captured from below, ;
 385:  ! then from above ;
 386:J P[104] 10% FINE ;
 387:J P[105] 10% FINE ;
 388:  WAIT   3.10(sec) ;
 389:J P[106] 10% FINE ;
 390:J P[107] 10% FINE ;
 391:  WAIT   3.10(sec) ;
 392:  ! zerocal stage 2: ;
 393:  ! pose 25 of 43, ;
 394:  ! captured from below, ;
 395:  ! then from above ;
 396:J P[108] 10% FINE ;
 397:J P[109] 10% FINE ;
 398:  WAIT   3.10(sec) ;
 399:J P[110] 10% FINE ;
 400:J P[111] 10% FINE ;
 401:  WAIT   3.10(sec) ;
 402:  ! zerocal stage 2: ;
 403:  ! pose 26 of 43, ;
 404:  ! captured from below, ;
 405:  ! then from above ;
 406:J P[112] 10% FINE ;
 407:J P[113] 10% FINE ;
 408:  WAIT   3.10(sec) ;
 409:J P[114] 10% FINE ;
 410:J P[115] 10% FINE ;
 411:  WAIT   3.10(sec) ;
 412:  ! zerocal stage 2: ;
 413:  ! pose 27 of 43, ;
 414:  ! captured from below, ;
 415:  ! then from above ;
 416:J P[116] 10% FINE ;
 417:J P[117] 10% FINE ;
 418:  WAIT   3.10(sec) ;
 419:J P[118] 10% FINE ;
 420:J P[119] 10% FINE ;
 421:  WAIT   3.10(sec) ;
 422:  ! zerocal stage 2: ;
 423:  ! pose 28 of 43, ;
 424:  ! captured from below, ;
 425:  ! then from above ;
 426:J P[120] 10% FINE ;
 427:J P[121] 10% FINE ;
 428:  WAIT   3.10(sec) ;
 429:J P[122] 10% FINE ;
 430:J P[123] 10% FINE ;
 431:  WAIT   3.10(sec) ;
 432:  ! zerocal stage 2: ;
 433:  ! pose 29 of 43, ;
 434:  ! captured from below, ;
 435:  ! then from above ;
 436:J P[124] 10% FINE ;
 437:J P[125] 10% FINE ;
 438:  WAIT   3.10(sec) ;
 439:J P[126] 10% FINE ;
 440:J P[127] 10% FINE ;
 441:  WAIT   3.10(sec) ;
 442:  ! zerocal stage 2: ;
 443:  ! pose 30 of 43, ;
 444:  ! captured from below, ;
 445:  ! then from above ;
 446:J P[128] 10% FINE ;
 447:J P[129] 10% FINE ;
 448:  WAIT   3.10(sec) ;
 449:J P[130] 10% FINE ;
 450:J P[131] 10% FINE ;
 451:  WAIT   3.10(sec) ;
 452:  ! zerocal stage 2: ;
 453:  ! pose 31 of 43, ;
 454:  ! captured from below, ;
 455:  ! then from above ;
 456:J P[132] 10% FINE ;
 457:J P[133] 10% FINE ;
 458:  WAIT   3.10(sec) ;
 459:J P[134] 10% FINE ;
 460:J P[135] 10% FINE ;
 461:  WAIT   3.10(sec) ;
 462:  ! zerocal stage 2: ;
 463:  ! pose 32 of 43, ;
 464:  ! captured from below, ;
 465:  ! then from above ;
 466:J P[136] 10% FINE ;
 467:J P[137] 10% FINE ;
 468:  WAIT   3.10(sec) ;
 469:J P[138] 10% FINE ;
 470:J P[139] 10% FINE ;
 471:  WAIT   3.10(sec) ;
 472:  ! zerocal stage 2: ;
 473:  ! pose 33 of 43, ;
 474:  ! captured from below, ;
 475:  ! then from above ;
 476:J P[140] 10% FINE ;
 477:J P[141] 10% FINE ;
 478:  WAIT   3.10(sec) ;
 479:J P[142] 10% FINE ;
 480:J P[143] 10% FINE ;
 481:  WAIT   3.10(sec) ;
 482:  ! zerocal stage 2: ;
 483:  ! pose 34 of 43, ;
 484:  ! captured from below, ;
 485:  ! then from above ;
 486:J P[144] 10% FINE ;
 487:J P[145] 10% FINE ;
 488:  WAIT   3.10(sec) ;
 489:J P[146] 10% FINE ;
 490:J P[147] 10% FINE ;
 491:  WAIT   3.10(sec) ;
 492:  ! zerocal stage 2: ;
 493:  ! pose 35 of 43, ;
 494:  ! captured from below, ;
 495:  ! then from above ;
 496:J P[148] 10% FINE ;
 497:J P[149] 10% FINE ;
 498:  WAIT   3.10(sec) ;
 499:J P[150] 10% FINE ;
 500:J P[151] 10% FINE ;
 501:  WAIT   3.10(sec) ;
 502:  ! zerocal stage 2: ;
 503:  ! pose 36 of 43, ;
 504:  ! captured from below, ;
 505:  ! then from above ;
 506:J P[152] 10% FINE ;
 507:J P[153] 10% FINE ;
 508:  WAIT   3.10(sec) ;
 509:J P[154] 10% FINE ;
 510:J P[155] 10% FINE ;
 511:  WAIT   3.10(sec) ;
 512:  ! zerocal stage 2: ;
 513:  ! pose 37 of 43, ;
 514:  ! captured from below, ;
 515:  ! then from above ;
 516:J P[156] 10% FINE ;
 517:J P[157] 10% FINE ;
 518:  WAIT   3.10(sec) ;
 519:J P[158] 10% FINE ;
 520:J P[159] 10% FINE ;
 521:  WAIT   3.10(sec) ;
 522:  ! zerocal stage 2: ;
 523:  ! pose 38 of 43, ;
 524:  ! captured from below, ;
 525:  ! then from above ;
 526:J P[160] 10% FINE ;
 527:J P[161] 10% FINE ;
 528:  WAIT   3.10(sec) ;
 529:J P[162] 10% FINE ;
 530:J P[163] 10% FINE ;
 531:  WAIT   3.10(sec) ;
 532:  ! zerocal stage 2: ;
 533:  ! pose 39 of 43, ;
 534:  ! captured from below, ;
 535:  ! then from above ;
 536:J P[164] 10% FINE ;
 537:J P[165] 10% FINE ;
 538:  WAIT   3.10(sec) ;
 539:J P[166] 10% FINE ;
 540:J P[167] 10% FINE ;
 541:  WAIT   3.10(sec) ;
 542:  ! zerocal stage 2: ;
 543:  ! pose 40 of 43, ;
 544:  ! captured from below, ;
 545:  ! then from above ;
 546:J P[168] 10% FINE ;
 547:J P[169] 10% FINE ;
 548:  WAIT   3.10(sec) ;
 549:J P[170] 10% FINE ;
 550:J P[171] 10% FINE ;
 551:  WAIT   3.10(sec) ;
 552:  ! zerocal stage 2: ;
 553:  ! pose 41 of 43, ;
 554:  ! captured from below, ;
 555:  ! then from above ;
 556:J P[172] 10% FINE ;
 557:J P[173] 10% FINE ;
 558:  WAIT   3.10(sec) ;
 559:J P[174] 10% FINE ;
 560:J P[175] 10% FINE ;
 561:  WAIT   3.10(sec) ;
 562:  ! zerocal stage 2: ;
 563:  ! pose 42 of 43, ;
 564:  ! captured from below, ;
 565:  ! then from above ;
 566:J P[176] 10% FINE ;
 567:J P[177] 10% FINE ;
 568:  WAIT   3.10(sec) ;
 569:J P[178] 10% FINE ;
 570:J P[179] 10% FINE ;
 571:  WAIT   3.10(sec) ;
 572:  ! zerocal stage 2: ;
 573:  ! pose 43 of 43, ;
 574:  ! captured from below, ;
 575:  ! then from above ;
 576:J P[180] 10% FINE ;
 577:J P[181] 10% FINE ;
 578:  WAIT   3.10(sec) ;
 579:J P[182] 10% FINE ;
 580:J P[183] 10% FINE ;
 581:  WAIT   3.10(sec) ;
 582:  ! zerocal: stage 2 ;
 583:  ! done; the robot ;
 584:  ! parks where the ;
 585:  ! pendant went on the ;
 586:  ! flange (tilted past ;
 587:  ! its range) to take ;
 588:  ! the pendant off ;
 589:J P[184] 10% FINE ;
 590:  MESSAGE[zerocal: take the] ;
 591:  MESSAGE[pendant off the] ;
 592:  MESSAGE[flange, then] ;
 593:  MESSAGE[continue: the] ;
 594:  MESSAGE[program ends and the] ;
 595:  MESSAGE[robot is free. On] ;
 596:  MESSAGE[the bench of stage] ;
 597:  MESSAGE[0, read the pendant] ;
 598:  MESSAGE[at its 4 headings as] ;
 599:  MESSAGE[it guides (the] ;
 600:  MESSAGE[closing bench] ;
 601:  MESSAGE[readings).] ;
 602:  PAUSE ;
 603:  ! zerocal: the robot's ;
 604:  ! part of the session ;
 605:  ! is done; the pendant ;
 606:  ! shows the result ;
 607:  ! after the closing ;
 608:  ! bench readings ;
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
	J1=   -90.000 deg,	J2=   -45.000 deg,	J3=   -15.923 deg,
	J4=    24.119 deg,	J5=   -32.040 deg,	J6=   -24.729 deg
};
P[12]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    29.623 deg,	J3=   -16.923 deg,
	J4=    23.119 deg,	J5=    11.960 deg,	J6=   -25.729 deg
};
P[13]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    30.623 deg,	J3=   -15.923 deg,
	J4=    24.119 deg,	J5=    12.960 deg,	J6=   -24.729 deg
};
P[14]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    34.623 deg,	J3=   -11.923 deg,
	J4=    28.119 deg,	J5=    16.960 deg,	J6=   -20.729 deg
};
P[15]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    30.623 deg,	J3=   -15.923 deg,
	J4=    24.119 deg,	J5=    12.960 deg,	J6=   -24.729 deg
};
P[16]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    60.295 deg,	J3=    10.639 deg,
	J4=   -39.765 deg,	J5=   -20.561 deg,	J6=    37.382 deg
};
P[17]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    61.295 deg,	J3=    11.639 deg,
	J4=   -38.765 deg,	J5=   -19.561 deg,	J6=    38.382 deg
};
P[18]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    65.295 deg,	J3=    15.639 deg,
	J4=   -34.765 deg,	J5=   -15.561 deg,	J6=    42.382 deg
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
	J1=   -91.000 deg,	J2=   -32.835 deg,	J3=   136.200 deg,
	J4=  -145.007 deg,	J5=   125.949 deg,	J6=  -153.792 deg
};
P[21]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -31.835 deg,	J3=   137.200 deg,
	J4=  -144.007 deg,	J5=   126.949 deg,	J6=  -152.792 deg
};
P[22]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -27.835 deg,	J3=   141.200 deg,
	J4=  -140.007 deg,	J5=   130.949 deg,	J6=  -148.792 deg
};
P[23]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -31.835 deg,	J3=   137.200 deg,
	J4=  -144.007 deg,	J5=   126.949 deg,	J6=  -152.792 deg
};
P[24]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -31.108 deg,	J3=   184.676 deg,
	J4=  -157.142 deg,	J5=    11.103 deg,	J6=   -24.493 deg
};
P[25]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -30.108 deg,	J3=   185.676 deg,
	J4=  -156.142 deg,	J5=    12.103 deg,	J6=   -23.493 deg
};
P[26]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -26.108 deg,	J3=   189.676 deg,
	J4=  -152.142 deg,	J5=    16.103 deg,	J6=   -19.493 deg
};
P[27]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -30.108 deg,	J3=   185.676 deg,
	J4=  -156.142 deg,	J5=    12.103 deg,	J6=   -23.493 deg
};
P[28]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -66.633 deg,	J3=   144.980 deg,
	J4=  -167.611 deg,	J5=   -37.725 deg,	J6=    -7.568 deg
};
P[29]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -65.633 deg,	J3=   145.980 deg,
	J4=  -166.611 deg,	J5=   -36.725 deg,	J6=    -6.568 deg
};
P[30]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -61.633 deg,	J3=   149.980 deg,
	J4=  -162.611 deg,	J5=   -32.725 deg,	J6=    -2.568 deg
};
P[31]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -65.633 deg,	J3=   145.980 deg,
	J4=  -166.611 deg,	J5=   -36.725 deg,	J6=    -6.568 deg
};
P[32]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -63.690 deg,	J3=   177.374 deg,
	J4=  -113.053 deg,	J5=    -4.526 deg,	J6=   -69.108 deg
};
P[33]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -62.690 deg,	J3=   178.374 deg,
	J4=  -112.053 deg,	J5=    -3.526 deg,	J6=   -68.108 deg
};
P[34]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -58.690 deg,	J3=   182.374 deg,
	J4=  -108.053 deg,	J5=     0.474 deg,	J6=   -64.108 deg
};
P[35]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -62.690 deg,	J3=   178.374 deg,
	J4=  -112.053 deg,	J5=    -3.526 deg,	J6=   -68.108 deg
};
P[36]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -75.702 deg,	J3=   159.383 deg,
	J4=    77.695 deg,	J5=    47.882 deg,	J6=   115.828 deg
};
P[37]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -74.702 deg,	J3=   160.383 deg,
	J4=    78.695 deg,	J5=    48.882 deg,	J6=   116.828 deg
};
P[38]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -70.702 deg,	J3=   164.383 deg,
	J4=    82.695 deg,	J5=    52.882 deg,	J6=   120.828 deg
};
P[39]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -74.702 deg,	J3=   160.383 deg,
	J4=    78.695 deg,	J5=    48.882 deg,	J6=   116.828 deg
};
P[40]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -5.214 deg,	J3=   152.490 deg,
	J4=   124.195 deg,	J5=   -39.833 deg,	J6=    47.493 deg
};
P[41]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    -4.214 deg,	J3=   153.490 deg,
	J4=   125.195 deg,	J5=   -38.833 deg,	J6=    48.493 deg
};
P[42]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    -0.214 deg,	J3=   157.490 deg,
	J4=   129.195 deg,	J5=   -34.833 deg,	J6=    52.493 deg
};
P[43]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    -4.214 deg,	J3=   153.490 deg,
	J4=   125.195 deg,	J5=   -38.833 deg,	J6=    48.493 deg
};
P[44]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -62.544 deg,	J3=   114.966 deg,
	J4=    10.497 deg,	J5=  -118.660 deg,	J6=     7.821 deg
};
P[45]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -61.544 deg,	J3=   115.966 deg,
	J4=    11.497 deg,	J5=  -117.660 deg,	J6=     8.821 deg
};
P[46]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -57.544 deg,	J3=   119.966 deg,
	J4=    15.497 deg,	J5=  -113.660 deg,	J6=    12.821 deg
};
P[47]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -61.544 deg,	J3=   115.966 deg,
	J4=    11.497 deg,	J5=  -117.660 deg,	J6=     8.821 deg
};
P[48]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -31.870 deg,	J3=   130.844 deg,
	J4=    26.210 deg,	J5=  -134.174 deg,	J6=    11.117 deg
};
P[49]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -30.870 deg,	J3=   131.844 deg,
	J4=    27.210 deg,	J5=  -133.174 deg,	J6=    12.117 deg
};
P[50]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -26.870 deg,	J3=   135.844 deg,
	J4=    31.210 deg,	J5=  -129.174 deg,	J6=    16.117 deg
};
P[51]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -30.870 deg,	J3=   131.844 deg,
	J4=    27.210 deg,	J5=  -133.174 deg,	J6=    12.117 deg
};
P[52]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -5.875 deg,	J3=   146.414 deg,
	J4=   -37.885 deg,	J5=  -137.011 deg,	J6=   -31.865 deg
};
P[53]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    -4.875 deg,	J3=   147.414 deg,
	J4=   -36.885 deg,	J5=  -136.011 deg,	J6=   -30.865 deg
};
P[54]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    -0.875 deg,	J3=   151.414 deg,
	J4=   -32.885 deg,	J5=  -132.011 deg,	J6=   -26.865 deg
};
P[55]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    -4.875 deg,	J3=   147.414 deg,
	J4=   -36.885 deg,	J5=  -136.011 deg,	J6=   -30.865 deg
};
P[56]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -75.889 deg,	J3=   104.729 deg,
	J4=  -164.574 deg,	J5=   -71.753 deg,	J6=    -6.276 deg
};
P[57]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -74.889 deg,	J3=   105.729 deg,
	J4=  -163.574 deg,	J5=   -70.753 deg,	J6=    -5.276 deg
};
P[58]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -70.889 deg,	J3=   109.729 deg,
	J4=  -159.574 deg,	J5=   -66.753 deg,	J6=    -1.276 deg
};
P[59]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -74.889 deg,	J3=   105.729 deg,
	J4=  -163.574 deg,	J5=   -70.753 deg,	J6=    -5.276 deg
};
P[60]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -33.996 deg,	J3=   104.916 deg,
	J4=  -155.761 deg,	J5=   -82.176 deg,	J6=   -13.142 deg
};
P[61]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -32.996 deg,	J3=   105.916 deg,
	J4=  -154.761 deg,	J5=   -81.176 deg,	J6=   -12.142 deg
};
P[62]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -28.996 deg,	J3=   109.916 deg,
	J4=  -150.761 deg,	J5=   -77.176 deg,	J6=    -8.142 deg
};
P[63]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -32.996 deg,	J3=   105.916 deg,
	J4=  -154.761 deg,	J5=   -81.176 deg,	J6=   -12.142 deg
};
P[64]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    -0.477 deg,	J3=    57.949 deg,
	J4=   -67.072 deg,	J5=   -75.878 deg,	J6=    26.398 deg
};
P[65]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.523 deg,	J3=    58.949 deg,
	J4=   -66.072 deg,	J5=   -74.878 deg,	J6=    27.398 deg
};
P[66]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=     4.523 deg,	J3=    62.949 deg,
	J4=   -62.072 deg,	J5=   -70.878 deg,	J6=    31.398 deg
};
P[67]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     0.523 deg,	J3=    58.949 deg,
	J4=   -66.072 deg,	J5=   -74.878 deg,	J6=    27.398 deg
};
P[68]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=     5.465 deg,	J3=    -4.340 deg,
	J4=  -102.288 deg,	J5=   -13.626 deg,	J6=    96.691 deg
};
P[69]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     6.465 deg,	J3=    -3.340 deg,
	J4=  -101.288 deg,	J5=   -12.626 deg,	J6=    97.691 deg
};
P[70]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    10.465 deg,	J3=     0.660 deg,
	J4=   -97.288 deg,	J5=    -8.626 deg,	J6=   101.691 deg
};
P[71]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     6.465 deg,	J3=    -3.340 deg,
	J4=  -101.288 deg,	J5=   -12.626 deg,	J6=    97.691 deg
};
P[72]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    34.809 deg,	J3=   -14.886 deg,
	J4=  -142.416 deg,	J5=   -17.126 deg,	J6=   135.967 deg
};
P[73]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    35.809 deg,	J3=   -13.886 deg,
	J4=  -141.416 deg,	J5=   -16.126 deg,	J6=   136.967 deg
};
P[74]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    39.809 deg,	J3=    -9.886 deg,
	J4=  -137.416 deg,	J5=   -12.126 deg,	J6=   140.967 deg
};
P[75]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    35.809 deg,	J3=   -13.886 deg,
	J4=  -141.416 deg,	J5=   -16.126 deg,	J6=   136.967 deg
};
P[76]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    61.880 deg,	J3=    17.074 deg,
	J4=  -172.242 deg,	J5=    21.746 deg,	J6=   175.793 deg
};
P[77]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    62.880 deg,	J3=    18.074 deg,
	J4=  -171.242 deg,	J5=    22.746 deg,	J6=   176.793 deg
};
P[78]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    66.880 deg,	J3=    22.074 deg,
	J4=  -167.242 deg,	J5=    26.746 deg,	J6=   180.793 deg
};
P[79]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    62.880 deg,	J3=    18.074 deg,
	J4=  -171.242 deg,	J5=    22.746 deg,	J6=   176.793 deg
};
P[80]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    72.910 deg,	J3=    -6.022 deg,
	J4=   -96.981 deg,	J5=   -20.064 deg,	J6=    97.598 deg
};
P[81]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    73.910 deg,	J3=    -5.022 deg,
	J4=   -95.981 deg,	J5=   -19.064 deg,	J6=    98.598 deg
};
P[82]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    77.910 deg,	J3=    -1.022 deg,
	J4=   -91.981 deg,	J5=   -15.064 deg,	J6=   102.598 deg
};
P[83]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    73.910 deg,	J3=    -5.022 deg,
	J4=   -95.981 deg,	J5=   -19.064 deg,	J6=    98.598 deg
};
P[84]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    73.671 deg,	J3=    14.236 deg,
	J4=   -42.633 deg,	J5=   -23.520 deg,	J6=    38.517 deg
};
P[85]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    74.671 deg,	J3=    15.236 deg,
	J4=   -41.633 deg,	J5=   -22.520 deg,	J6=    39.517 deg
};
P[86]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    78.671 deg,	J3=    19.236 deg,
	J4=   -37.633 deg,	J5=   -18.520 deg,	J6=    43.517 deg
};
P[87]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    74.671 deg,	J3=    15.236 deg,
	J4=   -41.633 deg,	J5=   -22.520 deg,	J6=    39.517 deg
};
P[88]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    61.085 deg,	J3=   -32.183 deg,
	J4=    38.722 deg,	J5=    34.160 deg,	J6=   -35.357 deg
};
P[89]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    62.085 deg,	J3=   -31.183 deg,
	J4=    39.722 deg,	J5=    35.160 deg,	J6=   -34.357 deg
};
P[90]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    66.085 deg,	J3=   -27.183 deg,
	J4=    43.722 deg,	J5=    39.160 deg,	J6=   -30.357 deg
};
P[91]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    62.085 deg,	J3=   -31.183 deg,
	J4=    39.722 deg,	J5=    35.160 deg,	J6=   -34.357 deg
};
P[92]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    29.623 deg,	J3=   -16.923 deg,
	J4=    23.119 deg,	J5=    11.960 deg,	J6=   -25.729 deg
};
P[93]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    30.623 deg,	J3=   -15.923 deg,
	J4=    24.119 deg,	J5=    12.960 deg,	J6=   -24.729 deg
};
P[94]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    34.623 deg,	J3=   -11.923 deg,
	J4=    28.119 deg,	J5=    16.960 deg,	J6=   -20.729 deg
};
P[95]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    30.623 deg,	J3=   -15.923 deg,
	J4=    24.119 deg,	J5=    12.960 deg,	J6=   -24.729 deg
};
P[96]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    30.383 deg,	J3=    -5.758 deg,
	J4=    63.012 deg,	J5=    -2.710 deg,	J6=   -59.518 deg
};
P[97]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    31.383 deg,	J3=    -4.758 deg,
	J4=    64.012 deg,	J5=    -1.710 deg,	J6=   -58.518 deg
};
P[98]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    35.383 deg,	J3=    -0.758 deg,
	J4=    68.012 deg,	J5=     2.290 deg,	J6=   -54.518 deg
};
P[99]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    31.383 deg,	J3=    -4.758 deg,
	J4=    64.012 deg,	J5=    -1.710 deg,	J6=   -58.518 deg
};
P[100]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    60.539 deg,	J3=    12.934 deg,
	J4=   143.144 deg,	J5=    18.744 deg,	J6=  -144.875 deg
};
P[101]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    61.539 deg,	J3=    13.934 deg,
	J4=   144.144 deg,	J5=    19.744 deg,	J6=  -143.875 deg
};
P[102]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    65.539 deg,	J3=    17.934 deg,
	J4=   148.144 deg,	J5=    23.744 deg,	J6=  -139.875 deg
};
P[103]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    61.539 deg,	J3=    13.934 deg,
	J4=   144.144 deg,	J5=    19.744 deg,	J6=  -143.875 deg
};
P[104]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    59.794 deg,	J3=    -1.699 deg,
	J4=   119.930 deg,	J5=     5.037 deg,	J6=  -120.309 deg
};
P[105]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    60.794 deg,	J3=    -0.699 deg,
	J4=   120.930 deg,	J5=     6.037 deg,	J6=  -119.309 deg
};
P[106]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    64.794 deg,	J3=     3.301 deg,
	J4=   124.930 deg,	J5=    10.037 deg,	J6=  -115.309 deg
};
P[107]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    60.794 deg,	J3=    -0.699 deg,
	J4=   120.930 deg,	J5=     6.037 deg,	J6=  -119.309 deg
};
P[108]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    61.663 deg,	J3=   -31.904 deg,
	J4=   163.172 deg,	J5=   -28.709 deg,	J6=  -169.031 deg
};
P[109]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    62.663 deg,	J3=   -30.904 deg,
	J4=   164.172 deg,	J5=   -27.709 deg,	J6=  -168.031 deg
};
P[110]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    66.663 deg,	J3=   -26.904 deg,
	J4=   168.172 deg,	J5=   -23.709 deg,	J6=  -164.031 deg
};
P[111]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    62.663 deg,	J3=   -30.904 deg,
	J4=   164.172 deg,	J5=   -27.709 deg,	J6=  -168.031 deg
};
P[112]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    73.791 deg,	J3=    29.671 deg,
	J4=    82.688 deg,	J5=   -91.617 deg,	J6=   -54.543 deg
};
P[113]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    74.791 deg,	J3=    30.671 deg,
	J4=    83.688 deg,	J5=   -90.617 deg,	J6=   -53.543 deg
};
P[114]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    78.791 deg,	J3=    34.671 deg,
	J4=    87.688 deg,	J5=   -86.617 deg,	J6=   -49.543 deg
};
P[115]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    74.791 deg,	J3=    30.671 deg,
	J4=    83.688 deg,	J5=   -90.617 deg,	J6=   -53.543 deg
};
P[116]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    73.584 deg,	J3=    97.974 deg,
	J4=   -55.853 deg,	J5=  -100.936 deg,	J6=   -12.029 deg
};
P[117]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    74.584 deg,	J3=    98.974 deg,
	J4=   -54.853 deg,	J5=   -99.936 deg,	J6=   -11.029 deg
};
P[118]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    78.584 deg,	J3=   102.974 deg,
	J4=   -50.853 deg,	J5=   -95.936 deg,	J6=    -7.029 deg
};
P[119]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    74.584 deg,	J3=    98.974 deg,
	J4=   -54.853 deg,	J5=   -99.936 deg,	J6=   -11.029 deg
};
P[120]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    61.151 deg,	J3=   102.154 deg,
	J4=   147.102 deg,	J5=   104.895 deg,	J6=  -185.738 deg
};
P[121]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    62.151 deg,	J3=   103.154 deg,
	J4=   148.102 deg,	J5=   105.895 deg,	J6=  -184.738 deg
};
P[122]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    66.151 deg,	J3=   107.154 deg,
	J4=   152.102 deg,	J5=   109.895 deg,	J6=  -180.738 deg
};
P[123]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    62.151 deg,	J3=   103.154 deg,
	J4=   148.102 deg,	J5=   105.895 deg,	J6=  -184.738 deg
};
P[124]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    35.542 deg,	J3=    19.898 deg,
	J4=    71.902 deg,	J5=   115.732 deg,	J6=  -114.509 deg
};
P[125]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    36.542 deg,	J3=    20.898 deg,
	J4=    72.902 deg,	J5=   116.732 deg,	J6=  -113.509 deg
};
P[126]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    40.542 deg,	J3=    24.898 deg,
	J4=    76.902 deg,	J5=   120.732 deg,	J6=  -109.509 deg
};
P[127]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    36.542 deg,	J3=    20.898 deg,
	J4=    72.902 deg,	J5=   116.732 deg,	J6=  -113.509 deg
};
P[128]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=     5.414 deg,	J3=   -41.505 deg,
	J4=   119.194 deg,	J5=   121.182 deg,	J6=   -43.990 deg
};
P[129]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     6.414 deg,	J3=   -40.505 deg,
	J4=   120.194 deg,	J5=   122.182 deg,	J6=   -42.990 deg
};
P[130]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    10.414 deg,	J3=   -36.505 deg,
	J4=   124.194 deg,	J5=   126.182 deg,	J6=   -38.990 deg
};
P[131]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     6.414 deg,	J3=   -40.505 deg,
	J4=   120.194 deg,	J5=   122.182 deg,	J6=   -42.990 deg
};
P[132]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -64.341 deg,	J3=    10.831 deg,
	J4=   114.517 deg,	J5=    19.584 deg,	J6=  -118.523 deg
};
P[133]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -63.341 deg,	J3=    11.831 deg,
	J4=   115.517 deg,	J5=    20.584 deg,	J6=  -117.523 deg
};
P[134]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -59.341 deg,	J3=    15.831 deg,
	J4=   119.517 deg,	J5=    24.584 deg,	J6=  -113.523 deg
};
P[135]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -63.341 deg,	J3=    11.831 deg,
	J4=   115.517 deg,	J5=    20.584 deg,	J6=  -117.523 deg
};
P[136]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -75.788 deg,	J3=     7.937 deg,
	J4=   136.710 deg,	J5=     4.882 deg,	J6=  -135.996 deg
};
P[137]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -74.788 deg,	J3=     8.937 deg,
	J4=   137.710 deg,	J5=     5.882 deg,	J6=  -134.996 deg
};
P[138]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -70.788 deg,	J3=    12.937 deg,
	J4=   141.710 deg,	J5=     9.882 deg,	J6=  -130.996 deg
};
P[139]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -74.788 deg,	J3=     8.937 deg,
	J4=   137.710 deg,	J5=     5.882 deg,	J6=  -134.996 deg
};
P[140]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -75.521 deg,	J3=    11.539 deg,
	J4=   118.703 deg,	J5=    33.359 deg,	J6=  -117.346 deg
};
P[141]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -74.521 deg,	J3=    12.539 deg,
	J4=   119.703 deg,	J5=    34.359 deg,	J6=  -116.346 deg
};
P[142]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -70.521 deg,	J3=    16.539 deg,
	J4=   123.703 deg,	J5=    38.359 deg,	J6=  -112.346 deg
};
P[143]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -74.521 deg,	J3=    12.539 deg,
	J4=   119.703 deg,	J5=    34.359 deg,	J6=  -116.346 deg
};
P[144]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -63.674 deg,	J3=   -17.136 deg,
	J4=    56.140 deg,	J5=    18.128 deg,	J6=   -54.090 deg
};
P[145]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -62.674 deg,	J3=   -16.136 deg,
	J4=    57.140 deg,	J5=    19.128 deg,	J6=   -53.090 deg
};
P[146]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -58.674 deg,	J3=   -12.136 deg,
	J4=    61.140 deg,	J5=    23.128 deg,	J6=   -49.090 deg
};
P[147]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -62.674 deg,	J3=   -16.136 deg,
	J4=    57.140 deg,	J5=    19.128 deg,	J6=   -53.090 deg
};
P[148]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=     6.029 deg,	J3=   -37.124 deg,
	J4=   -48.051 deg,	J5=  -134.195 deg,	J6=   143.544 deg
};
P[149]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     7.029 deg,	J3=   -36.124 deg,
	J4=   -47.051 deg,	J5=  -133.195 deg,	J6=   144.544 deg
};
P[150]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    11.029 deg,	J3=   -32.124 deg,
	J4=   -43.051 deg,	J5=  -129.195 deg,	J6=   148.544 deg
};
P[151]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     7.029 deg,	J3=   -36.124 deg,
	J4=   -47.051 deg,	J5=  -133.195 deg,	J6=   144.544 deg
};
P[152]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -65.549 deg,	J3=    31.328 deg,
	J4=  -120.191 deg,	J5=  -119.980 deg,	J6=    41.685 deg
};
P[153]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -64.549 deg,	J3=    32.328 deg,
	J4=  -119.191 deg,	J5=  -118.980 deg,	J6=    42.685 deg
};
P[154]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -60.549 deg,	J3=    36.328 deg,
	J4=  -115.191 deg,	J5=  -114.980 deg,	J6=    46.685 deg
};
P[155]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -64.549 deg,	J3=    32.328 deg,
	J4=  -119.191 deg,	J5=  -118.980 deg,	J6=    42.685 deg
};
P[156]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=   -75.885 deg,	J3=     1.767 deg,
	J4=  -157.412 deg,	J5=     2.064 deg,	J6=   153.891 deg
};
P[157]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -74.885 deg,	J3=     2.767 deg,
	J4=  -156.412 deg,	J5=     3.064 deg,	J6=   154.891 deg
};
P[158]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=   -70.885 deg,	J3=     6.767 deg,
	J4=  -152.412 deg,	J5=     7.064 deg,	J6=   158.891 deg
};
P[159]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -74.885 deg,	J3=     2.767 deg,
	J4=  -156.412 deg,	J5=     3.064 deg,	J6=   154.891 deg
};
P[160]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=     8.341 deg,	J3=  -148.304 deg,
	J4=   -69.510 deg,	J5=   122.340 deg,	J6=   -49.310 deg
};
P[161]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     9.341 deg,	J3=  -147.304 deg,
	J4=   -68.510 deg,	J5=   123.340 deg,	J6=   -48.310 deg
};
P[162]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    13.341 deg,	J3=  -143.304 deg,
	J4=   -64.510 deg,	J5=   127.340 deg,	J6=   -44.310 deg
};
P[163]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=     9.341 deg,	J3=  -147.304 deg,
	J4=   -68.510 deg,	J5=   123.340 deg,	J6=   -48.310 deg
};
P[164]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    59.242 deg,	J3=  -183.160 deg,
	J4=    17.248 deg,	J5=    -3.415 deg,	J6=  -193.474 deg
};
P[165]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    60.242 deg,	J3=  -182.160 deg,
	J4=    18.248 deg,	J5=    -2.415 deg,	J6=  -192.474 deg
};
P[166]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    64.242 deg,	J3=  -178.160 deg,
	J4=    22.248 deg,	J5=     1.585 deg,	J6=  -188.474 deg
};
P[167]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    60.242 deg,	J3=  -182.160 deg,
	J4=    18.248 deg,	J5=    -2.415 deg,	J6=  -192.474 deg
};
P[168]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    73.274 deg,	J3=  -211.087 deg,
	J4=   -64.041 deg,	J5=  -132.115 deg,	J6=   -51.949 deg
};
P[169]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    74.274 deg,	J3=  -210.087 deg,
	J4=   -63.041 deg,	J5=  -131.115 deg,	J6=   -50.949 deg
};
P[170]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    78.274 deg,	J3=  -206.087 deg,
	J4=   -59.041 deg,	J5=  -127.115 deg,	J6=   -46.949 deg
};
P[171]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    74.274 deg,	J3=  -210.087 deg,
	J4=   -63.041 deg,	J5=  -131.115 deg,	J6=   -50.949 deg
};
P[172]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    36.216 deg,	J3=   -58.829 deg,
	J4=     6.274 deg,	J5=  -125.709 deg,	J6=  -181.524 deg
};
P[173]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    37.216 deg,	J3=   -57.829 deg,
	J4=     7.274 deg,	J5=  -124.709 deg,	J6=  -180.524 deg
};
P[174]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    41.216 deg,	J3=   -53.829 deg,
	J4=    11.274 deg,	J5=  -120.709 deg,	J6=  -176.524 deg
};
P[175]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    37.216 deg,	J3=   -57.829 deg,
	J4=     7.274 deg,	J5=  -124.709 deg,	J6=  -180.524 deg
};
P[176]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    29.623 deg,	J3=   -16.923 deg,
	J4=    23.119 deg,	J5=    11.960 deg,	J6=   -25.729 deg
};
P[177]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    30.623 deg,	J3=   -15.923 deg,
	J4=    24.119 deg,	J5=    12.960 deg,	J6=   -24.729 deg
};
P[178]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    34.623 deg,	J3=   -11.923 deg,
	J4=    28.119 deg,	J5=    16.960 deg,	J6=   -20.729 deg
};
P[179]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    30.623 deg,	J3=   -15.923 deg,
	J4=    24.119 deg,	J5=    12.960 deg,	J6=   -24.729 deg
};
P[180]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -91.000 deg,	J2=    30.383 deg,	J3=    -5.758 deg,
	J4=    63.012 deg,	J5=    -2.710 deg,	J6=   -59.518 deg
};
P[181]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    31.383 deg,	J3=    -4.758 deg,
	J4=    64.012 deg,	J5=    -1.710 deg,	J6=   -58.518 deg
};
P[182]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -86.000 deg,	J2=    35.383 deg,	J3=    -0.758 deg,
	J4=    68.012 deg,	J5=     2.290 deg,	J6=   -54.518 deg
};
P[183]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=    31.383 deg,	J3=    -4.758 deg,
	J4=    64.012 deg,	J5=    -1.710 deg,	J6=   -58.518 deg
};
P[184]{
   GP1:
	UF : 0, UT : 0,	
	J1=   -90.000 deg,	J2=   -45.000 deg,	J3=   -15.923 deg,
	J4=    24.119 deg,	J5=   -32.040 deg,	J6=   -24.729 deg
};
/END
