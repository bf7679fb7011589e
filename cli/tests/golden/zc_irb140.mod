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
    ! pendant off and continue: the program ends there and the robot is free. Then read the pendant on
    ! the bench as in stage 0 (4 headings, turned by hand about a quarter turn on the same spot
    ! between them).
    ! Speed: joint moves at 10 % of each joint's maximum speed, exact stops.
    ! Dwell 3.1 s at each capture: settling 1 s (stated default) + the pendant's 2 s still window + 2
    ! sensor periods of 0.05 s.
    ! Predicted robot time 11.1 min, until the pendant is off the flange: motion 200 s, dwell 279 s
    ! (90 captures), 3 mountings 180 s, operator OKs 10 s; then the closing bench readings, 42 s, the
    ! robot free.
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
    CONST jointtarget zc_t11:=[[-90.00000,-45.00000,-92.52572,-125.55291,31.20962,130.83023],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t12:=[[-91.00000,-74.17956,-93.52572,-126.55291,30.20962,129.83023],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t13:=[[-90.00000,-73.17956,-92.52572,-125.55291,31.20962,130.83023],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t14:=[[-86.00000,-69.17956,-88.52572,-121.55291,35.20962,134.83023],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t15:=[[-90.00000,-73.17956,-92.52572,-125.55291,31.20962,130.83023],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t16:=[[-91.00000,-4.65398,-176.46637,-4.30253,1.63117,-3.56084],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t17:=[[-90.00000,-3.65398,-175.46637,-3.30253,2.63117,-2.56084],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t18:=[[-86.00000,0.34602,-171.46637,0.69747,6.63117,1.43916],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t19:=[[-90.00000,-3.65398,-175.46637,-3.30253,2.63117,-2.56084],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t20:=[[-91.00000,-9.24437,-221.70209,50.65324,59.37193,-31.90226],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t21:=[[-90.00000,-8.24437,-220.70209,51.65324,60.37193,-30.90226],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t22:=[[-86.00000,-4.24437,-216.70209,55.65324,64.37193,-26.90226],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t23:=[[-90.00000,-8.24437,-220.70209,51.65324,60.37193,-30.90226],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t24:=[[-91.00000,25.14421,-225.45690,19.26224,23.62779,-21.21176],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t25:=[[-90.00000,26.14421,-224.45690,20.26224,24.62779,-20.21176],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t26:=[[-86.00000,30.14421,-220.45690,24.26224,28.62779,-16.21176],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t27:=[[-90.00000,26.14421,-224.45690,20.26224,24.62779,-20.21176],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t28:=[[-91.00000,-3.00218,-173.84120,70.40369,-22.62188,-69.54098],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t29:=[[-90.00000,-2.00218,-172.84120,71.40369,-21.62188,-68.54098],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t30:=[[-86.00000,1.99782,-168.84120,75.40369,-17.62188,-64.54098],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t31:=[[-90.00000,-2.00218,-172.84120,71.40369,-21.62188,-68.54098],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t32:=[[-91.00000,-36.60594,-146.67123,148.22613,3.66348,-154.79671],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t33:=[[-90.00000,-35.60594,-145.67123,149.22613,4.66348,-153.79671],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t34:=[[-86.00000,-31.60594,-141.67123,153.22613,8.66348,-149.79671],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t35:=[[-90.00000,-35.60594,-145.67123,149.22613,4.66348,-153.79671],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t36:=[[-91.00000,-62.50998,-114.02744,103.28639,15.33454,-111.56189],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t37:=[[-90.00000,-61.50998,-113.02744,104.28639,16.33454,-110.56189],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t38:=[[-86.00000,-57.50998,-109.02744,108.28639,20.33454,-106.56189],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t39:=[[-90.00000,-61.50998,-113.02744,104.28639,16.33454,-110.56189],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t40:=[[-91.00000,28.20450,-54.19616,80.36859,-111.11344,66.50680],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t41:=[[-90.00000,29.20450,-53.19616,81.36859,-110.11344,67.50680],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t42:=[[-86.00000,33.20450,-49.19616,85.36859,-106.11344,71.50680],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t43:=[[-90.00000,29.20450,-53.19616,81.36859,-110.11344,67.50680],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t44:=[[-91.00000,59.53654,-87.55478,163.87932,-21.89299,16.67723],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t45:=[[-90.00000,60.53654,-86.55478,164.87932,-20.89299,17.67723],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t46:=[[-86.00000,64.53654,-82.55478,168.87932,-16.89299,21.67723],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t47:=[[-90.00000,60.53654,-86.55478,164.87932,-20.89299,17.67723],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t48:=[[-91.00000,35.89177,-46.23574,165.77532,-12.14650,7.85936],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t49:=[[-90.00000,36.89177,-45.23574,166.77532,-11.14650,8.85936],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t50:=[[-86.00000,40.89177,-41.23574,170.77532,-7.14650,12.85936],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t51:=[[-90.00000,36.89177,-45.23574,166.77532,-11.14650,8.85936],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t52:=[[-91.00000,36.14389,-13.45158,152.01317,22.19879,26.79768],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t53:=[[-90.00000,37.14389,-12.45158,153.01317,23.19879,27.79768],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t54:=[[-86.00000,41.14389,-8.45158,157.01317,27.19879,31.79768],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t55:=[[-90.00000,37.14389,-12.45158,153.01317,23.19879,27.79768],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t56:=[[-91.00000,33.28125,-34.93369,90.82399,33.10053,89.37622],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t57:=[[-90.00000,34.28125,-33.93369,91.82399,34.10053,90.37622],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t58:=[[-86.00000,38.28125,-29.93369,95.82399,38.10053,94.37622],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t59:=[[-90.00000,34.28125,-33.93369,91.82399,34.10053,90.37622],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t60:=[[-91.00000,2.89351,23.77474,63.87335,-58.39826,121.87918],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t61:=[[-90.00000,3.89351,24.77474,64.87335,-57.39826,122.87918],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t62:=[[-86.00000,7.89351,28.77474,68.87335,-53.39826,126.87918],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t63:=[[-90.00000,3.89351,24.77474,64.87335,-57.39826,122.87918],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t64:=[[-91.00000,-65.94064,3.26665,-37.33598,-114.58650,-17.28775],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t65:=[[-90.00000,-64.94064,4.26665,-36.33598,-113.58650,-16.28775],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t66:=[[-86.00000,-60.94064,8.26665,-32.33598,-109.58650,-12.28775],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t67:=[[-90.00000,-64.94064,4.26665,-36.33598,-113.58650,-16.28775],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t68:=[[-91.00000,-74.61238,6.62156,-8.86412,-109.11995,-7.91099],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t69:=[[-90.00000,-73.61238,7.62156,-7.86412,-108.11995,-6.91099],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t70:=[[-86.00000,-69.61238,11.62156,-3.86412,-104.11995,-2.91099],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t71:=[[-90.00000,-73.61238,7.62156,-7.86412,-108.11995,-6.91099],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t72:=[[-91.00000,-75.37751,-16.46983,22.07211,-85.50605,-5.04608],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t73:=[[-90.00000,-74.37751,-15.46983,23.07211,-84.50605,-4.04608],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t74:=[[-86.00000,-70.37751,-11.46983,27.07211,-80.50605,-0.04608],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t75:=[[-90.00000,-74.37751,-15.46983,23.07211,-84.50605,-4.04608],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t76:=[[-91.00000,-61.94135,-51.62413,21.11796,-75.95614,-10.65547],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t77:=[[-90.00000,-60.94135,-50.62413,22.11796,-74.95614,-9.65547],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t78:=[[-86.00000,-56.94135,-46.62413,26.11796,-70.95614,-5.65547],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t79:=[[-90.00000,-60.94135,-50.62413,22.11796,-74.95614,-9.65547],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t80:=[[-91.00000,-66.08134,-59.91734,37.43130,-57.85613,-22.37128],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t81:=[[-90.00000,-65.08134,-58.91734,38.43130,-56.85613,-21.37128],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t82:=[[-86.00000,-61.08134,-54.91734,42.43130,-52.85613,-17.37128],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t83:=[[-90.00000,-65.08134,-58.91734,38.43130,-56.85613,-21.37128],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t84:=[[-91.00000,-74.72123,-62.79862,17.94843,-44.42761,-18.80137],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t85:=[[-90.00000,-73.72123,-61.79862,18.94843,-43.42761,-17.80137],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t86:=[[-86.00000,-69.72123,-57.79862,22.94843,-39.42761,-13.80137],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t87:=[[-90.00000,-73.72123,-61.79862,18.94843,-43.42761,-17.80137],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t88:=[[-91.00000,-59.52567,-115.20023,-81.58773,-10.81286,81.33545],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t89:=[[-90.00000,-58.52567,-114.20023,-80.58773,-9.81286,82.33545],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t90:=[[-86.00000,-54.52567,-110.20023,-76.58773,-5.81286,86.33545],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t91:=[[-90.00000,-58.52567,-114.20023,-80.58773,-9.81286,82.33545],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t92:=[[-91.00000,-74.17956,-93.52572,-126.55291,30.20962,129.83023],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t93:=[[-90.00000,-73.17956,-92.52572,-125.55291,31.20962,130.83023],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t94:=[[-86.00000,-69.17956,-88.52572,-121.55291,35.20962,134.83023],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t95:=[[-90.00000,-73.17956,-92.52572,-125.55291,31.20962,130.83023],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t96:=[[-91.00000,-58.83577,-95.09530,-136.88234,28.54974,135.13067],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t97:=[[-90.00000,-57.83577,-94.09530,-135.88234,29.54974,136.13067],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t98:=[[-86.00000,-53.83577,-90.09530,-131.88234,33.54974,140.13067],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t99:=[[-90.00000,-57.83577,-94.09530,-135.88234,29.54974,136.13067],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t100:=[[-91.00000,-32.52491,-112.35545,-145.37869,42.17993,149.61530],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t101:=[[-90.00000,-31.52491,-111.35545,-144.37869,43.17993,150.61530],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t102:=[[-86.00000,-27.52491,-107.35545,-140.37869,47.17993,154.61530],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t103:=[[-90.00000,-31.52491,-111.35545,-144.37869,43.17993,150.61530],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t104:=[[-91.00000,-63.46087,-50.90063,-62.95795,101.94040,163.65327],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t105:=[[-90.00000,-62.46087,-49.90063,-61.95795,102.94040,164.65327],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t106:=[[-86.00000,-58.46087,-45.90063,-57.95795,106.94040,168.65327],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t107:=[[-90.00000,-62.46087,-49.90063,-61.95795,102.94040,164.65327],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t108:=[[-91.00000,73.39037,-185.37191,168.21253,72.80539,176.82471],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t109:=[[-90.00000,74.39037,-184.37191,169.21253,73.80539,177.82471],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t110:=[[-86.00000,78.39037,-180.37191,173.21253,77.80539,181.82471],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t111:=[[-90.00000,74.39037,-184.37191,169.21253,73.80539,177.82471],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t112:=[[-91.00000,73.90099,-196.36789,47.06061,-65.90625,-19.91652],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t113:=[[-90.00000,74.90099,-195.36789,48.06061,-64.90625,-18.91652],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t114:=[[-86.00000,78.90099,-191.36789,52.06061,-60.90625,-14.91652],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t115:=[[-90.00000,74.90099,-195.36789,48.06061,-64.90625,-18.91652],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t116:=[[-91.00000,62.83020,-203.83282,35.43364,-54.71690,-33.00528],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t117:=[[-90.00000,63.83020,-202.83282,36.43364,-53.71690,-32.00528],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t118:=[[-86.00000,67.83020,-198.83282,40.43364,-49.71690,-28.00528],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t119:=[[-90.00000,63.83020,-202.83282,36.43364,-53.71690,-32.00528],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t120:=[[-91.00000,60.01263,-173.63374,-37.23500,-70.81141,11.83765],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t121:=[[-90.00000,61.01263,-172.63374,-36.23500,-69.81141,12.83765],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t122:=[[-86.00000,65.01263,-168.63374,-32.23500,-65.81141,16.83765],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t123:=[[-90.00000,61.01263,-172.63374,-36.23500,-69.81141,12.83765],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t124:=[[-91.00000,59.06440,-221.27727,-157.24850,16.92929,155.88113],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t125:=[[-90.00000,60.06440,-220.27727,-156.24850,17.92929,156.88113],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t126:=[[-86.00000,64.06440,-216.27727,-152.24850,21.92929,160.88113],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t127:=[[-90.00000,60.06440,-220.27727,-156.24850,17.92929,156.88113],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t128:=[[-91.00000,-35.30281,-95.66632,-123.42933,-112.62784,30.85351],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t129:=[[-90.00000,-34.30281,-94.66632,-122.42933,-111.62784,31.85351],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t130:=[[-86.00000,-30.30281,-90.66632,-118.42933,-107.62784,35.85351],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t131:=[[-90.00000,-34.30281,-94.66632,-122.42933,-111.62784,31.85351],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t132:=[[-91.00000,58.56045,-47.23592,-97.05109,-95.32730,-98.81283],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t133:=[[-90.00000,59.56045,-46.23592,-96.05109,-94.32730,-97.81283],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t134:=[[-86.00000,63.56045,-42.23592,-92.05109,-90.32730,-93.81283],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t135:=[[-90.00000,59.56045,-46.23592,-96.05109,-94.32730,-97.81283],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t136:=[[-91.00000,60.95207,-65.75136,-26.18354,2.87873,-154.97165],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t137:=[[-90.00000,61.95207,-64.75136,-25.18354,3.87873,-153.97165],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t138:=[[-86.00000,65.95207,-60.75136,-21.18354,7.87873,-149.97165],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t139:=[[-90.00000,61.95207,-64.75136,-25.18354,3.87873,-153.97165],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t140:=[[-91.00000,60.38789,-61.16713,-98.30108,-0.17981,-81.89637],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t141:=[[-90.00000,61.38789,-60.16713,-97.30108,0.82019,-80.89637],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t142:=[[-86.00000,65.38789,-56.16713,-93.30108,4.82019,-76.89637],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t143:=[[-90.00000,61.38789,-60.16713,-97.30108,0.82019,-80.89637],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t144:=[[-91.00000,-8.20970,-162.68633,-176.70261,15.04062,-179.52890],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t145:=[[-90.00000,-7.20970,-161.68633,-175.70261,16.04062,-178.52890],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t146:=[[-86.00000,-3.20970,-157.68633,-171.70261,20.04062,-174.52890],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t147:=[[-90.00000,-7.20970,-161.68633,-175.70261,16.04062,-178.52890],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t148:=[[-91.00000,73.45254,-135.09310,-48.95211,73.26805,-161.91770],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t149:=[[-90.00000,74.45254,-134.09310,-47.95211,74.26805,-160.91770],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t150:=[[-86.00000,78.45254,-130.09310,-43.95211,78.26805,-156.91770],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t151:=[[-90.00000,74.45254,-134.09310,-47.95211,74.26805,-160.91770],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t152:=[[-91.00000,73.36305,-214.11356,108.15984,68.82699,-131.28533],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t153:=[[-90.00000,74.36305,-213.11356,109.15984,69.82699,-130.28533],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t154:=[[-86.00000,78.36305,-209.11356,113.15984,73.82699,-126.28533],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t155:=[[-90.00000,74.36305,-213.11356,109.15984,69.82699,-130.28533],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t156:=[[-91.00000,-35.21276,-80.97191,11.42044,107.45177,-172.58634],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t157:=[[-90.00000,-34.21276,-79.97191,12.42044,108.45177,-171.58634],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t158:=[[-86.00000,-30.21276,-75.97191,16.42044,112.45177,-167.58634],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t159:=[[-90.00000,-34.21276,-79.97191,12.42044,108.45177,-171.58634],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t160:=[[-91.00000,-43.60791,-20.29451,-127.58300,108.38228,-160.81376],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t161:=[[-90.00000,-42.60791,-19.29451,-126.58300,109.38228,-159.81376],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t162:=[[-86.00000,-38.60791,-15.29451,-122.58300,113.38228,-155.81376],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t163:=[[-90.00000,-42.60791,-19.29451,-126.58300,109.38228,-159.81376],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t164:=[[-91.00000,-75.24934,15.76834,-10.29502,55.04352,-177.04119],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t165:=[[-90.00000,-74.24934,16.76834,-9.29502,56.04352,-176.04119],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t166:=[[-86.00000,-70.24934,20.76834,-5.29502,60.04352,-172.04119],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t167:=[[-90.00000,-74.24934,16.76834,-9.29502,56.04352,-176.04119],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t168:=[[-91.00000,-62.77942,-5.94063,-153.73946,-65.93484,-14.52043],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t169:=[[-90.00000,-61.77942,-4.94063,-152.73946,-64.93484,-13.52043],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t170:=[[-86.00000,-57.77942,-0.94063,-148.73946,-60.93484,-9.52043],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t171:=[[-90.00000,-61.77942,-4.94063,-152.73946,-64.93484,-13.52043],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t172:=[[-91.00000,0.00993,11.64060,-180.73941,11.18260,-2.05352],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t173:=[[-90.00000,1.00993,12.64060,-179.73941,12.18260,-1.05352],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t174:=[[-86.00000,5.00993,16.64060,-175.73941,16.18260,2.94648],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t175:=[[-90.00000,1.00993,12.64060,-179.73941,12.18260,-1.05352],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t176:=[[-91.00000,-74.17956,-93.52572,-126.55291,30.20962,129.83023],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t177:=[[-90.00000,-73.17956,-92.52572,-125.55291,31.20962,130.83023],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t178:=[[-86.00000,-69.17956,-88.52572,-121.55291,35.20962,134.83023],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t179:=[[-90.00000,-73.17956,-92.52572,-125.55291,31.20962,130.83023],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t180:=[[-91.00000,-58.83577,-95.09530,-136.88234,28.54974,135.13067],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t181:=[[-90.00000,-57.83577,-94.09530,-135.88234,29.54974,136.13067],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t182:=[[-86.00000,-53.83577,-90.09530,-131.88234,33.54974,140.13067],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t183:=[[-90.00000,-57.83577,-94.09530,-135.88234,29.54974,136.13067],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t184:=[[-90.00000,-45.00000,-92.52572,-125.55291,31.20962,130.83023],[9E9,9E9,9E9,9E9,9E9,9E9]];
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
        MoveAbsJ zc_t12,v100 \T:=1.531,fine,tool0;
        MoveAbsJ zc_t13,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t14,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t15,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 2 of 43, captured from below, then from above
        MoveAbsJ zc_t16,v100 \T:=3.892,fine,tool0;
        MoveAbsJ zc_t17,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t18,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t19,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 3 of 43, captured from below, then from above
        MoveAbsJ zc_t20,v100 \T:=2.156,fine,tool0;
        MoveAbsJ zc_t21,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t22,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t23,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 4 of 43, captured from below, then from above
        MoveAbsJ zc_t24,v100 \T:=1.699,fine,tool0;
        MoveAbsJ zc_t25,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t26,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t27,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 5 of 43, captured from below, then from above
        MoveAbsJ zc_t28,v100 \T:=2.325,fine,tool0;
        MoveAbsJ zc_t29,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t30,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t31,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 6 of 43, captured from below, then from above
        MoveAbsJ zc_t32,v100 \T:=2.658,fine,tool0;
        MoveAbsJ zc_t33,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t34,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t35,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 7 of 43, captured from below, then from above
        MoveAbsJ zc_t36,v100 \T:=1.800,fine,tool0;
        MoveAbsJ zc_t37,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t38,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t39,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 8 of 43, captured from below, then from above
        MoveAbsJ zc_t40,v100 \T:=4.589,fine,tool0;
        MoveAbsJ zc_t41,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t42,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t43,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 9 of 43, captured from below, then from above
        MoveAbsJ zc_t44,v100 \T:=2.974,fine,tool0;
        MoveAbsJ zc_t45,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t46,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t47,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 10 of 43, captured from below, then from above
        MoveAbsJ zc_t48,v100 \T:=1.929,fine,tool0;
        MoveAbsJ zc_t49,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t50,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t51,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 11 of 43, captured from below, then from above
        MoveAbsJ zc_t52,v100 \T:=1.601,fine,tool0;
        MoveAbsJ zc_t53,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t54,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t55,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 12 of 43, captured from below, then from above
        MoveAbsJ zc_t56,v100 \T:=2.251,fine,tool0;
        MoveAbsJ zc_t57,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t58,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t59,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 13 of 43, captured from below, then from above
        MoveAbsJ zc_t60,v100 \T:=3.093,fine,tool0;
        MoveAbsJ zc_t61,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t62,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t63,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 14 of 43, captured from below, then from above
        MoveAbsJ zc_t64,v100 \T:=3.769,fine,tool0;
        MoveAbsJ zc_t65,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t66,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t67,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 15 of 43, captured from below, then from above
        MoveAbsJ zc_t68,v100 \T:=1.287,fine,tool0;
        MoveAbsJ zc_t69,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t70,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t71,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 16 of 43, captured from below, then from above
        MoveAbsJ zc_t72,v100 \T:=1.355,fine,tool0;
        MoveAbsJ zc_t73,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t74,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t75,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 17 of 43, captured from below, then from above
        MoveAbsJ zc_t76,v100 \T:=1.769,fine,tool0;
        MoveAbsJ zc_t77,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t78,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t79,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 18 of 43, captured from below, then from above
        MoveAbsJ zc_t80,v100 \T:=0.997,fine,tool0;
        MoveAbsJ zc_t81,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t82,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t83,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 19 of 43, captured from below, then from above
        MoveAbsJ zc_t84,v100 \T:=1.093,fine,tool0;
        MoveAbsJ zc_t85,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t86,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t87,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 20 of 43, captured from below, then from above
        MoveAbsJ zc_t88,v100 \T:=3.316,fine,tool0;
        MoveAbsJ zc_t89,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t90,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t91,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 21 of 43, captured from below, then from above
        MoveAbsJ zc_t92,v100 \T:=1.800,fine,tool0;
        MoveAbsJ zc_t93,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t94,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t95,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 22 of 43, captured from below, then from above
        MoveAbsJ zc_t96,v100 \T:=0.937,fine,tool0;
        MoveAbsJ zc_t97,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t98,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t99,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 23 of 43, captured from below, then from above
        MoveAbsJ zc_t100,v100 \T:=1.376,fine,tool0;
        MoveAbsJ zc_t101,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t102,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t103,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 24 of 43, captured from below, then from above
        MoveAbsJ zc_t104,v100 \T:=2.785,fine,tool0;
        MoveAbsJ zc_t105,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t106,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t107,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 25 of 43, captured from below, then from above
        MoveAbsJ zc_t108,v100 \T:=6.917,fine,tool0;
        MoveAbsJ zc_t109,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t110,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t111,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 26 of 43, captured from below, then from above
        MoveAbsJ zc_t112,v100 \T:=5.049,fine,tool0;
        MoveAbsJ zc_t113,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t114,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t115,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 27 of 43, captured from below, then from above
        MoveAbsJ zc_t116,v100 \T:=0.905,fine,tool0;
        MoveAbsJ zc_t117,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t118,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t119,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 28 of 43, captured from below, then from above
        MoveAbsJ zc_t120,v100 \T:=2.570,fine,tool0;
        MoveAbsJ zc_t121,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t122,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t123,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 29 of 43, captured from below, then from above
        MoveAbsJ zc_t124,v100 \T:=3.885,fine,tool0;
        MoveAbsJ zc_t125,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t126,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t127,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 30 of 43, captured from below, then from above
        MoveAbsJ zc_t128,v100 \T:=5.171,fine,tool0;
        MoveAbsJ zc_t129,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t130,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t131,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 31 of 43, captured from below, then from above
        MoveAbsJ zc_t132,v100 \T:=4.078,fine,tool0;
        MoveAbsJ zc_t133,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t134,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t135,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 32 of 43, captured from below, then from above
        MoveAbsJ zc_t136,v100 \T:=3.224,fine,tool0;
        MoveAbsJ zc_t137,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t138,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t139,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 33 of 43, captured from below, then from above
        MoveAbsJ zc_t140,v100 \T:=2.555,fine,tool0;
        MoveAbsJ zc_t141,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t142,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t143,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 34 of 43, captured from below, then from above
        MoveAbsJ zc_t144,v100 \T:=4.321,fine,tool0;
        MoveAbsJ zc_t145,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t146,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t147,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 35 of 43, captured from below, then from above
        MoveAbsJ zc_t148,v100 \T:=4.044,fine,tool0;
        MoveAbsJ zc_t149,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t150,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t151,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 36 of 43, captured from below, then from above
        MoveAbsJ zc_t152,v100 \T:=4.860,fine,tool0;
        MoveAbsJ zc_t153,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t154,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t155,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 37 of 43, captured from below, then from above
        MoveAbsJ zc_t156,v100 \T:=5.461,fine,tool0;
        MoveAbsJ zc_t157,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t158,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t159,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 38 of 43, captured from below, then from above
        MoveAbsJ zc_t160,v100 \T:=4.413,fine,tool0;
        MoveAbsJ zc_t161,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t162,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t163,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 39 of 43, captured from below, then from above
        MoveAbsJ zc_t164,v100 \T:=3.754,fine,tool0;
        MoveAbsJ zc_t165,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t166,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t167,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 40 of 43, captured from below, then from above
        MoveAbsJ zc_t168,v100 \T:=4.536,fine,tool0;
        MoveAbsJ zc_t169,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t170,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t171,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 41 of 43, captured from below, then from above
        MoveAbsJ zc_t172,v100 \T:=2.835,fine,tool0;
        MoveAbsJ zc_t173,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t174,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t175,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 42 of 43, captured from below, then from above
        MoveAbsJ zc_t176,v100 \T:=4.461,fine,tool0;
        MoveAbsJ zc_t177,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t178,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t179,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 43 of 43, captured from below, then from above
        MoveAbsJ zc_t180,v100 \T:=0.937,fine,tool0;
        MoveAbsJ zc_t181,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t182,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t183,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal: stage 2 done; the robot parks where the pendant went on the flange (tilted past its
        ! range) to take the pendant off
        MoveAbsJ zc_t184,v100 \T:=0.877,fine,tool0;
        TPWrite "zerocal: take the pendant off the";
        TPWrite "flange, then continue: the program ends";
        TPWrite "and the robot is free. On the bench of";
        TPWrite "stage 0, read the pendant at its 4";
        TPWrite "headings as it guides (the closing bench";
        TPWrite "readings).";
        STOP;
        ! zerocal: the robot's part of the session is done; the pendant shows the result after the closing
        ! bench readings
    ENDPROC
ENDMODULE
