%%%
  VERSION:1
  LANGUAGE:ENGLISH
%%%

MODULE ZC_IRB140
    ! zerocal robot program: a joint-zero calibration session.
    ! Robot ABB IRB 140T-6/0.81 (IRB 140T; ROS-I model irb140t_6_81) (profile abb-irb140); 43 stage-2
    ! poses. Written by zerocal 0.1.0; targets in the controller's joint degrees.
    ! Every pose is captured twice: first with every joint arriving moving positive (from 1 deg
    ! below), then, after every joint has gone 4 deg past it, moving negative (from above). The
    ! pendant averages the two: the middle of every gear's backlash.
    ! Stop: clip the pendant to the upper arm (the robot stands with the pendant tilted past its
    ! range, so it cannot capture early). Stage 1: the stage-1 pose twice, then joint 1 turned by 180
    ! deg twice (an OK on the pendant arms the first). Stop: move the pendant to the flange (tilted
    ! again). Stage 2: the plan's poses in its order, twice each; load the same plan into the pendant
    ! (plan set).
    ! Closing bench readings: the robot parks where the pendant went on the flange and stops; take the
    ! pendant off and read it on the bench as in stage 0 (4 headings, turned by hand about a quarter
    ! turn on the same spot between them). The program ends there.
    ! Speed: joint moves at 10 % of each joint's maximum speed, exact stops.
    ! Dwell 3.1 s at each capture: settling 1 s (stated default) + the pendant's 2 s still window + 2
    ! sensor periods of 0.05 s.
    ! Predicted robot time 12.1 min, the closing bench readings included: motion 216 s, dwell 291 s
    ! (94 captures), 3 mountings 180 s, operator OKs 40 s.
    ! WARNING: the path is NOT checked for collisions with the cell, the pendant or its bracket. Check
    ! the cell, then step through the program once at reduced speed (T1) before running it.
    CONST jointtarget zc_t1:=[[-90.00000,-45.00000,-90.00000,0.00000,0.00000,0.00000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t2:=[[-91.00000,-1.00000,-91.00000,-1.00000,-1.00000,-1.00000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t3:=[[-90.00000,0.00000,-90.00000,0.00000,0.00000,0.00000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t4:=[[-86.00000,4.00000,-86.00000,4.00000,4.00000,4.00000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t5:=[[-90.00000,0.00000,-90.00000,0.00000,0.00000,0.00000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t6:=[[89.00000,0.00000,-90.00000,0.00000,0.00000,0.00000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t7:=[[89.00000,-1.00000,-91.00000,-1.00000,-1.00000,-1.00000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t8:=[[90.00000,0.00000,-90.00000,0.00000,0.00000,0.00000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t9:=[[94.00000,4.00000,-86.00000,4.00000,4.00000,4.00000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t10:=[[90.00000,0.00000,-90.00000,0.00000,0.00000,0.00000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t11:=[[-90.00000,-45.00000,-184.37191,169.21253,73.80539,177.82471],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t12:=[[-91.00000,73.39037,-185.37191,168.21253,72.80539,176.82471],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t13:=[[-90.00000,74.39037,-184.37191,169.21253,73.80539,177.82471],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t14:=[[-86.00000,78.39037,-180.37191,173.21253,77.80539,181.82471],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t15:=[[-90.00000,74.39037,-184.37191,169.21253,73.80539,177.82471],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t16:=[[-91.00000,36.42226,-111.08745,28.08775,77.55545,175.63413],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t17:=[[-90.00000,37.42226,-110.08745,29.08775,78.55545,176.63413],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t18:=[[-86.00000,41.42226,-106.08745,33.08775,82.55545,180.63413],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t19:=[[-90.00000,37.42226,-110.08745,29.08775,78.55545,176.63413],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t20:=[[-91.00000,61.01693,-133.52898,9.13593,71.24679,176.79763],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t21:=[[-90.00000,62.01693,-132.52898,10.13593,72.24679,177.79763],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t22:=[[-86.00000,66.01693,-128.52898,14.13593,76.24679,181.79763],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t23:=[[-90.00000,62.01693,-132.52898,10.13593,72.24679,177.79763],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t24:=[[-91.00000,-2.37311,-175.94575,-20.44182,-5.82883,19.50275],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t25:=[[-90.00000,-1.37311,-174.94575,-19.44182,-4.82883,20.50275],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t26:=[[-86.00000,2.62689,-170.94575,-15.44182,-0.82883,24.50275],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t27:=[[-90.00000,-1.37311,-174.94575,-19.44182,-4.82883,20.50275],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t28:=[[-91.00000,-59.52567,-115.20023,-81.58773,-10.81286,81.33545],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t29:=[[-90.00000,-58.52567,-114.20023,-80.58773,-9.81286,82.33545],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t30:=[[-86.00000,-54.52567,-110.20023,-76.58773,-5.81286,86.33545],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t31:=[[-90.00000,-58.52567,-114.20023,-80.58773,-9.81286,82.33545],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t32:=[[-91.00000,-74.17956,-93.52572,-126.55291,30.20962,129.83023],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t33:=[[-90.00000,-73.17956,-92.52572,-125.55291,31.20962,130.83023],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t34:=[[-86.00000,-69.17956,-88.52572,-121.55291,35.20962,134.83023],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t35:=[[-90.00000,-73.17956,-92.52572,-125.55291,31.20962,130.83023],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t36:=[[-91.00000,-61.11448,-108.24513,-149.88743,8.52415,153.84109],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t37:=[[-90.00000,-60.11448,-107.24513,-148.88743,9.52415,154.84109],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t38:=[[-86.00000,-56.11448,-103.24513,-144.88743,13.52415,158.84109],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t39:=[[-90.00000,-60.11448,-107.24513,-148.88743,9.52415,154.84109],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t40:=[[-91.00000,-32.52491,-112.35545,-145.37869,42.17993,149.61530],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t41:=[[-90.00000,-31.52491,-111.35545,-144.37869,43.17993,150.61530],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t42:=[[-86.00000,-27.52491,-107.35545,-140.37869,47.17993,154.61530],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t43:=[[-90.00000,-31.52491,-111.35545,-144.37869,43.17993,150.61530],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t44:=[[-91.00000,-33.57805,-148.71928,-82.12420,-3.11195,82.54804],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t45:=[[-90.00000,-32.57805,-147.71928,-81.12420,-2.11195,83.54804],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t46:=[[-86.00000,-28.57805,-143.71928,-77.12420,1.88805,87.54804],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t47:=[[-90.00000,-32.57805,-147.71928,-81.12420,-2.11195,83.54804],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t48:=[[-91.00000,-4.64954,-205.84380,-111.58164,-56.39181,124.12062],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t49:=[[-90.00000,-3.64954,-204.84380,-110.58164,-55.39181,125.12062],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t50:=[[-86.00000,0.35046,-200.84380,-106.58164,-51.39181,129.12062],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t51:=[[-90.00000,-3.64954,-204.84380,-110.58164,-55.39181,125.12062],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t52:=[[-91.00000,59.06440,-221.27727,-157.24850,16.92929,155.88113],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t53:=[[-90.00000,60.06440,-220.27727,-156.24850,17.92929,156.88113],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t54:=[[-86.00000,64.06440,-216.27727,-152.24850,21.92929,160.88113],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t55:=[[-90.00000,60.06440,-220.27727,-156.24850,17.92929,156.88113],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t56:=[[-91.00000,60.18983,-173.68058,-42.96651,-69.62178,8.18236],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t57:=[[-90.00000,61.18983,-172.68058,-41.96651,-68.62178,9.18236],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t58:=[[-86.00000,65.18983,-168.68058,-37.96651,-64.62178,13.18236],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t59:=[[-90.00000,61.18983,-172.68058,-41.96651,-68.62178,9.18236],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t60:=[[-91.00000,73.19777,-135.26359,-137.69291,-63.99027,-26.21819],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t61:=[[-90.00000,74.19777,-134.26359,-136.69291,-62.99027,-25.21819],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t62:=[[-86.00000,78.19777,-130.26359,-132.69291,-58.99027,-21.21819],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t63:=[[-90.00000,74.19777,-134.26359,-136.69291,-62.99027,-25.21819],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t64:=[[-91.00000,38.06221,-26.98337,-16.72680,-17.94122,-169.69636],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t65:=[[-90.00000,39.06221,-25.98337,-15.72680,-16.94122,-168.69636],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t66:=[[-86.00000,43.06221,-21.98337,-11.72680,-12.94122,-164.69636],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t67:=[[-90.00000,39.06221,-25.98337,-15.72680,-16.94122,-168.69636],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t68:=[[-91.00000,60.20475,-87.97831,-21.43265,22.94544,-167.05254],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t69:=[[-90.00000,61.20475,-86.97831,-20.43265,23.94544,-166.05254],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t70:=[[-86.00000,65.20475,-82.97831,-16.43265,27.94544,-162.05254],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t71:=[[-90.00000,61.20475,-86.97831,-20.43265,23.94544,-166.05254],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t72:=[[-91.00000,73.45254,-135.09310,-48.95211,73.26805,-161.91770],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t73:=[[-90.00000,74.45254,-134.09310,-47.95211,74.26805,-160.91770],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t74:=[[-86.00000,78.45254,-130.09310,-43.95211,78.26805,-156.91770],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t75:=[[-90.00000,74.45254,-134.09310,-47.95211,74.26805,-160.91770],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t76:=[[-91.00000,73.90099,-196.36789,47.06061,-65.90625,-19.91652],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t77:=[[-90.00000,74.90099,-195.36789,48.06061,-64.90625,-18.91652],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t78:=[[-86.00000,78.90099,-191.36789,52.06061,-60.90625,-14.91652],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t79:=[[-90.00000,74.90099,-195.36789,48.06061,-64.90625,-18.91652],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t80:=[[-91.00000,25.14421,-225.45690,19.26224,23.62779,-21.21176],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t81:=[[-90.00000,26.14421,-224.45690,20.26224,24.62779,-20.21176],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t82:=[[-86.00000,30.14421,-220.45690,24.26224,28.62779,-16.21176],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t83:=[[-90.00000,26.14421,-224.45690,20.26224,24.62779,-20.21176],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t84:=[[-91.00000,-7.87347,-182.95316,27.58315,2.64566,-35.35437],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t85:=[[-90.00000,-6.87347,-181.95316,28.58315,3.64566,-34.35437],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t86:=[[-86.00000,-2.87347,-177.95316,32.58315,7.64566,-30.35437],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t87:=[[-90.00000,-6.87347,-181.95316,28.58315,3.64566,-34.35437],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t88:=[[-91.00000,-3.00218,-173.84120,70.40369,-22.62188,-69.54098],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t89:=[[-90.00000,-2.00218,-172.84120,71.40369,-21.62188,-68.54098],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t90:=[[-86.00000,1.99782,-168.84120,75.40369,-17.62188,-64.54098],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t91:=[[-90.00000,-2.00218,-172.84120,71.40369,-21.62188,-68.54098],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t92:=[[-91.00000,73.39037,-185.37191,168.21253,72.80539,176.82471],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t93:=[[-90.00000,74.39037,-184.37191,169.21253,73.80539,177.82471],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t94:=[[-86.00000,78.39037,-180.37191,173.21253,77.80539,181.82471],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t95:=[[-90.00000,74.39037,-184.37191,169.21253,73.80539,177.82471],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t96:=[[-91.00000,-33.36319,-161.89295,91.05567,-84.39274,-102.65239],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t97:=[[-90.00000,-32.36319,-160.89295,92.05567,-83.39274,-101.65239],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t98:=[[-86.00000,-28.36319,-156.89295,96.05567,-79.39274,-97.65239],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t99:=[[-90.00000,-32.36319,-160.89295,92.05567,-83.39274,-101.65239],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t100:=[[-91.00000,-62.73887,-92.46342,75.68443,-67.44609,-60.41252],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t101:=[[-90.00000,-61.73887,-91.46342,76.68443,-66.44609,-59.41252],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t102:=[[-86.00000,-57.73887,-87.46342,80.68443,-62.44609,-55.41252],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t103:=[[-90.00000,-61.73887,-91.46342,76.68443,-66.44609,-59.41252],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t104:=[[-91.00000,-75.37751,-16.46983,22.07211,-85.50605,-5.04608],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t105:=[[-90.00000,-74.37751,-15.46983,23.07211,-84.50605,-4.04608],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t106:=[[-86.00000,-70.37751,-11.46983,27.07211,-80.50605,-0.04608],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t107:=[[-90.00000,-74.37751,-15.46983,23.07211,-84.50605,-4.04608],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t108:=[[-91.00000,-65.94064,3.26665,-37.33598,-114.58650,-17.28775],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t109:=[[-90.00000,-64.94064,4.26665,-36.33598,-113.58650,-16.28775],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t110:=[[-86.00000,-60.94064,8.26665,-32.33598,-109.58650,-12.28775],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t111:=[[-90.00000,-64.94064,4.26665,-36.33598,-113.58650,-16.28775],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t112:=[[-91.00000,-37.78172,-35.14242,-42.79988,-111.58526,-11.88500],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t113:=[[-90.00000,-36.78172,-34.14242,-41.79988,-110.58526,-10.88500],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t114:=[[-86.00000,-32.78172,-30.14242,-37.79988,-106.58526,-6.88500],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t115:=[[-90.00000,-36.78172,-34.14242,-41.79988,-110.58526,-10.88500],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t116:=[[-91.00000,-35.30281,-95.66632,-123.42933,-112.62784,30.85351],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t117:=[[-90.00000,-34.30281,-94.66632,-122.42933,-111.62784,31.85351],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t118:=[[-86.00000,-30.30281,-90.66632,-118.42933,-107.62784,35.85351],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t119:=[[-90.00000,-34.30281,-94.66632,-122.42933,-111.62784,31.85351],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t120:=[[-91.00000,-62.77942,-5.94063,-153.73946,-65.93484,-14.52043],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t121:=[[-90.00000,-61.77942,-4.94063,-152.73946,-64.93484,-13.52043],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t122:=[[-86.00000,-57.77942,-0.94063,-148.73946,-60.93484,-9.52043],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t123:=[[-90.00000,-61.77942,-4.94063,-152.73946,-64.93484,-13.52043],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t124:=[[-91.00000,0.00993,11.64060,-180.73941,11.18260,-2.05352],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t125:=[[-90.00000,1.00993,12.64060,-179.73941,12.18260,-1.05352],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t126:=[[-86.00000,5.00993,16.64060,-175.73941,16.18260,2.94648],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t127:=[[-90.00000,1.00993,12.64060,-179.73941,12.18260,-1.05352],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t128:=[[-91.00000,30.98035,-0.93392,-76.03986,105.68180,-60.43634],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t129:=[[-90.00000,31.98035,0.06608,-75.03986,106.68180,-59.43634],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t130:=[[-86.00000,35.98035,4.06608,-71.03986,110.68180,-55.43634],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t131:=[[-90.00000,31.98035,0.06608,-75.03986,106.68180,-59.43634],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t132:=[[-91.00000,-43.60791,-20.29451,-127.58300,108.38228,-160.81376],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t133:=[[-90.00000,-42.60791,-19.29451,-126.58300,109.38228,-159.81376],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t134:=[[-86.00000,-38.60791,-15.29451,-122.58300,113.38228,-155.81376],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t135:=[[-90.00000,-42.60791,-19.29451,-126.58300,109.38228,-159.81376],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t136:=[[-91.00000,-60.46594,14.64967,-105.55880,108.69512,-137.86105],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t137:=[[-90.00000,-59.46594,15.64967,-104.55880,109.69512,-136.86105],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t138:=[[-86.00000,-55.46594,19.64967,-100.55880,113.69512,-132.86105],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t139:=[[-90.00000,-59.46594,15.64967,-104.55880,109.69512,-136.86105],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t140:=[[-91.00000,-64.76999,10.34112,-36.38991,52.85930,-157.73882],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t141:=[[-90.00000,-63.76999,11.34112,-35.38991,53.85930,-156.73882],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t142:=[[-86.00000,-59.76999,15.34112,-31.38991,57.85930,-152.73882],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t143:=[[-90.00000,-63.76999,11.34112,-35.38991,53.85930,-156.73882],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t144:=[[-91.00000,-75.24934,15.76834,-10.29502,55.04352,-177.04119],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t145:=[[-90.00000,-74.24934,16.76834,-9.29502,56.04352,-176.04119],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t146:=[[-86.00000,-70.24934,20.76834,-5.29502,60.04352,-172.04119],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t147:=[[-90.00000,-74.24934,16.76834,-9.29502,56.04352,-176.04119],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t148:=[[-91.00000,-74.68687,18.05966,161.74734,-59.65737,12.66807],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t149:=[[-90.00000,-73.68687,19.05966,162.74734,-58.65737,13.66807],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t150:=[[-86.00000,-69.68687,23.05966,166.74734,-54.65737,17.66807],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t151:=[[-90.00000,-73.68687,19.05966,162.74734,-58.65737,13.66807],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t152:=[[-91.00000,3.76870,22.84945,81.87325,-82.57429,118.47476],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t153:=[[-90.00000,4.76870,23.84945,82.87325,-81.57429,119.47476],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t154:=[[-86.00000,8.76870,27.84945,86.87325,-77.57429,123.47476],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t155:=[[-90.00000,4.76870,23.84945,82.87325,-81.57429,119.47476],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t156:=[[-91.00000,63.20031,-46.10164,37.20863,-26.01207,149.16803],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t157:=[[-90.00000,64.20031,-45.10164,38.20863,-25.01207,150.16803],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t158:=[[-86.00000,68.20031,-41.10164,42.20863,-21.01207,154.16803],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t159:=[[-90.00000,64.20031,-45.10164,38.20863,-25.01207,150.16803],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t160:=[[-91.00000,60.13727,-54.01728,105.43938,11.66132,69.10057],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t161:=[[-90.00000,61.13727,-53.01728,106.43938,12.66132,70.10057],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t162:=[[-86.00000,65.13727,-49.01728,110.43938,16.66132,74.10057],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t163:=[[-90.00000,61.13727,-53.01728,106.43938,12.66132,70.10057],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t164:=[[-91.00000,35.89177,-46.23574,165.77532,-12.14650,7.85936],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t165:=[[-90.00000,36.89177,-45.23574,166.77532,-11.14650,8.85936],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t166:=[[-86.00000,40.89177,-41.23574,170.77532,-7.14650,12.85936],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t167:=[[-90.00000,36.89177,-45.23574,166.77532,-11.14650,8.85936],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t168:=[[-91.00000,2.68084,-36.84615,153.87844,-39.93932,14.41430],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t169:=[[-90.00000,3.68084,-35.84615,154.87844,-38.93932,15.41430],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t170:=[[-86.00000,7.68084,-31.84615,158.87844,-34.93932,19.41430],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t171:=[[-90.00000,3.68084,-35.84615,154.87844,-38.93932,15.41430],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t172:=[[-91.00000,-59.40336,-134.03162,176.89344,-7.50798,176.82403],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t173:=[[-90.00000,-58.40336,-133.03162,177.89344,-6.50798,177.82403],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t174:=[[-86.00000,-54.40336,-129.03162,181.89344,-2.50798,181.82403],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t175:=[[-90.00000,-58.40336,-133.03162,177.89344,-6.50798,177.82403],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t176:=[[-91.00000,73.39037,-185.37191,168.21253,72.80539,176.82471],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t177:=[[-90.00000,74.39037,-184.37191,169.21253,73.80539,177.82471],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t178:=[[-86.00000,78.39037,-180.37191,173.21253,77.80539,181.82471],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t179:=[[-90.00000,74.39037,-184.37191,169.21253,73.80539,177.82471],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t180:=[[-91.00000,-33.36319,-161.89295,91.05567,-84.39274,-102.65239],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t181:=[[-90.00000,-32.36319,-160.89295,92.05567,-83.39274,-101.65239],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t182:=[[-86.00000,-28.36319,-156.89295,96.05567,-79.39274,-97.65239],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t183:=[[-90.00000,-32.36319,-160.89295,92.05567,-83.39274,-101.65239],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t184:=[[-90.00000,-45.00000,-184.37191,169.21253,73.80539,177.82471],[9E9,9E9,9E9,9E9,9E9,9E9]];
    PROC main()
        ! zerocal stage 1: the pendant goes on the upper arm here, tilted past its range so that it cannot
        ! capture yet
        ! from wherever the robot stands: speeddata v100, step through it
        MoveAbsJ zc_t1,v100,fine,tool0;
        TPWrite "zerocal: clip the pendant to the upper";
        TPWrite "arm (its screen at STAGE 1), then";
        TPWrite "continue.";
        STOP;
        ! zerocal stage 1: the stage-1 pose, captured from below, then from above
        MoveAbsJ zc_t2,v100 \T:=2.124,fine,tool0;
        MoveAbsJ zc_t3,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t4,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t5,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 1: joint 1 turned by 180 deg, captured from below, then from above
        MoveAbsJ zc_t6,v100 \T:=7.524,fine,tool0;
        MoveAbsJ zc_t7,v100 \T:=0.241,fine,tool0;
        MoveAbsJ zc_t8,v100 \T:=0.241,fine,tool0;
        TPWrite "zerocal: press OK on the pendant (after";
        TPWrite "the half turn only OK arms it), then";
        TPWrite "continue.";
        STOP;
        WaitTime 3.100;
        MoveAbsJ zc_t9,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t10,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal: joint 1 back; the pendant goes from the upper arm to the flange here, both tilted past
        ! its range
        MoveAbsJ zc_t11,v100 \T:=7.564,fine,tool0;
        TPWrite "zerocal: move the pendant from the upper";
        TPWrite "arm to the flange (its screen at POSE";
        TPWrite "1), then continue.";
        STOP;
        ! zerocal stage 2: pose 1 of 43, captured from below, then from above
        MoveAbsJ zc_t12,v100 \T:=5.099,fine,tool0;
        MoveAbsJ zc_t13,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t14,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t15,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 2 of 43, captured from below, then from above
        MoveAbsJ zc_t16,v100 \T:=4.444,fine,tool0;
        MoveAbsJ zc_t17,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t18,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t19,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 3 of 43, captured from below, then from above
        MoveAbsJ zc_t20,v100 \T:=1.307,fine,tool0;
        MoveAbsJ zc_t21,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t22,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t23,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 4 of 43, captured from below, then from above
        MoveAbsJ zc_t24,v100 \T:=4.172,fine,tool0;
        MoveAbsJ zc_t25,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t26,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t27,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 5 of 43, captured from below, then from above
        MoveAbsJ zc_t28,v100 \T:=2.690,fine,tool0;
        MoveAbsJ zc_t29,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t30,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t31,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 6 of 43, captured from below, then from above
        MoveAbsJ zc_t32,v100 \T:=1.800,fine,tool0;
        MoveAbsJ zc_t33,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t34,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t35,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 7 of 43, captured from below, then from above
        MoveAbsJ zc_t36,v100 \T:=1.200,fine,tool0;
        MoveAbsJ zc_t37,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t38,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t39,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 8 of 43, captured from below, then from above
        MoveAbsJ zc_t40,v100 \T:=1.467,fine,tool0;
        MoveAbsJ zc_t41,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t42,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t43,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 9 of 43, captured from below, then from above
        MoveAbsJ zc_t44,v100 \T:=2.253,fine,tool0;
        MoveAbsJ zc_t45,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t46,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t47,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 10 of 43, captured from below, then from above
        MoveAbsJ zc_t48,v100 \T:=2.614,fine,tool0;
        MoveAbsJ zc_t49,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t50,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t51,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 11 of 43, captured from below, then from above
        MoveAbsJ zc_t52,v100 \T:=2.872,fine,tool0;
        MoveAbsJ zc_t53,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t54,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t55,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 12 of 43, captured from below, then from above
        MoveAbsJ zc_t56,v100 \T:=3.959,fine,tool0;
        MoveAbsJ zc_t57,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t58,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t59,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 13 of 43, captured from below, then from above
        MoveAbsJ zc_t60,v100 \T:=3.183,fine,tool0;
        MoveAbsJ zc_t61,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t62,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t63,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 14 of 43, captured from below, then from above
        MoveAbsJ zc_t64,v100 \T:=4.504,fine,tool0;
        MoveAbsJ zc_t65,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t66,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t67,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 15 of 43, captured from below, then from above
        MoveAbsJ zc_t68,v100 \T:=2.763,fine,tool0;
        MoveAbsJ zc_t69,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t70,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t71,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 16 of 43, captured from below, then from above
        MoveAbsJ zc_t72,v100 \T:=2.229,fine,tool0;
        MoveAbsJ zc_t73,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t74,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t75,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 17 of 43, captured from below, then from above
        MoveAbsJ zc_t76,v100 \T:=4.417,fine,tool0;
        MoveAbsJ zc_t77,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t78,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t79,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 18 of 43, captured from below, then from above
        MoveAbsJ zc_t80,v100 \T:=2.983,fine,tool0;
        MoveAbsJ zc_t81,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t82,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t83,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 19 of 43, captured from below, then from above
        MoveAbsJ zc_t84,v100 \T:=1.974,fine,tool0;
        MoveAbsJ zc_t85,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t86,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t87,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 20 of 43, captured from below, then from above
        MoveAbsJ zc_t88,v100 \T:=1.685,fine,tool0;
        MoveAbsJ zc_t89,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t90,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t91,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 21 of 43, captured from below, then from above
        MoveAbsJ zc_t92,v100 \T:=6.107,fine,tool0;
        MoveAbsJ zc_t93,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t94,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t95,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 22 of 43, captured from below, then from above
        MoveAbsJ zc_t96,v100 \T:=6.887,fine,tool0;
        MoveAbsJ zc_t97,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t98,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t99,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 23 of 43, captured from below, then from above
        MoveAbsJ zc_t100,v100 \T:=3.010,fine,tool0;
        MoveAbsJ zc_t101,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t102,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t103,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 24 of 43, captured from below, then from above
        MoveAbsJ zc_t104,v100 \T:=3.263,fine,tool0;
        MoveAbsJ zc_t105,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t106,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t107,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 25 of 43, captured from below, then from above
        MoveAbsJ zc_t108,v100 \T:=2.202,fine,tool0;
        MoveAbsJ zc_t109,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t110,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t111,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 26 of 43, captured from below, then from above
        MoveAbsJ zc_t112,v100 \T:=1.894,fine,tool0;
        MoveAbsJ zc_t113,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t114,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t115,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 27 of 43, captured from below, then from above
        MoveAbsJ zc_t116,v100 \T:=2.791,fine,tool0;
        MoveAbsJ zc_t117,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t118,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t119,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 28 of 43, captured from below, then from above
        MoveAbsJ zc_t120,v100 \T:=3.791,fine,tool0;
        MoveAbsJ zc_t121,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t122,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t123,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 29 of 43, captured from below, then from above
        MoveAbsJ zc_t124,v100 \T:=2.835,fine,tool0;
        MoveAbsJ zc_t125,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t126,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t127,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 30 of 43, captured from below, then from above
        MoveAbsJ zc_t128,v100 \T:=3.404,fine,tool0;
        MoveAbsJ zc_t129,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t130,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t131,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 31 of 43, captured from below, then from above
        MoveAbsJ zc_t132,v100 \T:=3.387,fine,tool0;
        MoveAbsJ zc_t133,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t134,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t135,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 32 of 43, captured from below, then from above
        MoveAbsJ zc_t136,v100 \T:=1.684,fine,tool0;
        MoveAbsJ zc_t137,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t138,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t139,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 33 of 43, captured from below, then from above
        MoveAbsJ zc_t140,v100 \T:=2.417,fine,tool0;
        MoveAbsJ zc_t141,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t142,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t143,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 34 of 43, captured from below, then from above
        MoveAbsJ zc_t144,v100 \T:=1.221,fine,tool0;
        MoveAbsJ zc_t145,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t146,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t147,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 35 of 43, captured from below, then from above
        MoveAbsJ zc_t148,v100 \T:=5.275,fine,tool0;
        MoveAbsJ zc_t149,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t150,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t151,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 36 of 43, captured from below, then from above
        MoveAbsJ zc_t152,v100 \T:=3.462,fine,tool0;
        MoveAbsJ zc_t153,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t154,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t155,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 37 of 43, captured from below, then from above
        MoveAbsJ zc_t156,v100 \T:=3.069,fine,tool0;
        MoveAbsJ zc_t157,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t158,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t159,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 38 of 43, captured from below, then from above
        MoveAbsJ zc_t160,v100 \T:=2.456,fine,tool0;
        MoveAbsJ zc_t161,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t162,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t163,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 39 of 43, captured from below, then from above
        MoveAbsJ zc_t164,v100 \T:=2.172,fine,tool0;
        MoveAbsJ zc_t165,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t166,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t167,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 40 of 43, captured from below, then from above
        MoveAbsJ zc_t168,v100 \T:=1.732,fine,tool0;
        MoveAbsJ zc_t169,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t170,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t171,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 41 of 43, captured from below, then from above
        MoveAbsJ zc_t172,v100 \T:=4.241,fine,tool0;
        MoveAbsJ zc_t173,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t174,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t175,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 42 of 43, captured from below, then from above
        MoveAbsJ zc_t176,v100 \T:=5.635,fine,tool0;
        MoveAbsJ zc_t177,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t178,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t179,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 43 of 43, captured from below, then from above
        MoveAbsJ zc_t180,v100 \T:=6.887,fine,tool0;
        MoveAbsJ zc_t181,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t182,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t183,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal: stage 2 done; the robot parks where the pendant went on the flange (tilted past its
        ! range) for the closing bench readings
        MoveAbsJ zc_t184,v100 \T:=6.865,fine,tool0;
        TPWrite "zerocal: closing bench readings: take";
        TPWrite "the pendant off the flange to the bench";
        TPWrite "of stage 0 and read it at 4 headings,";
        TPWrite "turned by hand about a quarter turn on";
        TPWrite "the same spot between them, as the";
        TPWrite "pendant guides. Then continue.";
        STOP;
        ! zerocal: session done; the pendant shows the result
    ENDPROC
ENDMODULE
