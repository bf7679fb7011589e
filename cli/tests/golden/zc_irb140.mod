%%%
  VERSION:1
  LANGUAGE:ENGLISH
%%%

MODULE ZC_IRB140
    ! zerocal robot program: a joint-zero calibration session.
    ! Robot ABB IRB 140T-6/0.81 (IRB 140T; ROS-I model irb140t_6_81) (profile abb-irb140); 24 stage-2
    ! poses. Written by zerocal 0.1.0; targets in the controller's joint degrees.
    ! Every pose is captured twice: first with every joint arriving moving positive (from 1 deg
    ! below), then, after every joint has gone 4 deg past it, moving negative (from above). The
    ! pendant averages the two: the middle of every gear's backlash.
    ! Stop: clip the pendant to the upper arm (the robot stands with the pendant tilted past its
    ! range, so it cannot capture early). Stage 1: the stage-1 pose twice, then joint 1 turned by 180
    ! deg twice (an OK on the pendant arms the first). Stop: move the pendant to the flange (tilted
    ! again). Stage 2: the plan's poses in its order, twice each; load the same plan into the pendant
    ! (plan set).
    ! Closing reversal: the robot parks where the pendant went on the flange and stops; take the
    ! pendant off and reverse it on the bench as in stage 0 (two readings, turned 180 deg on the same
    ! spot between them). The program ends there.
    ! Speed: joint moves at 10 % of each joint's maximum speed, exact stops.
    ! Dwell 3.1 s at each capture: settling 1 s (stated default) + the pendant's 2 s still window + 2
    ! sensor periods of 0.05 s.
    ! Predicted robot time 8.7 min, the closing reversal included: motion 153 s, dwell 167 s (54
    ! captures), 3 mountings 180 s, operator OKs 20 s.
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
    CONST jointtarget zc_t11:=[[-90.00000,-45.00000,-31.60407,79.40106,-109.41682,-298.80311],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t12:=[[-91.00000,-1.00000,-32.60407,78.40106,-110.41682,-299.80311],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t13:=[[-90.00000,0.00000,-31.60407,79.40106,-109.41682,-298.80311],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t14:=[[-86.00000,4.00000,-27.60407,83.40106,-105.41682,-294.80311],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t15:=[[-90.00000,0.00000,-31.60407,79.40106,-109.41682,-298.80311],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t16:=[[-91.00000,-1.00000,31.10732,-35.50286,-35.05560,-152.21714],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t17:=[[-90.00000,0.00000,32.10732,-34.50286,-34.05560,-151.21714],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t18:=[[-86.00000,4.00000,36.10732,-30.50286,-30.05560,-147.21714],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t19:=[[-90.00000,0.00000,32.10732,-34.50286,-34.05560,-151.21714],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t20:=[[-91.00000,-1.00000,23.14932,-97.08309,-101.44817,-117.81348],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t21:=[[-90.00000,0.00000,24.14932,-96.08309,-100.44817,-116.81348],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t22:=[[-86.00000,4.00000,28.14932,-92.08309,-96.44817,-112.81348],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t23:=[[-90.00000,0.00000,24.14932,-96.08309,-100.44817,-116.81348],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t24:=[[-91.00000,-1.00000,-62.92496,-35.04074,-112.09156,-11.96417],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t25:=[[-90.00000,0.00000,-61.92496,-34.04074,-111.09156,-10.96417],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t26:=[[-86.00000,4.00000,-57.92496,-30.04074,-107.09156,-6.96417],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t27:=[[-90.00000,0.00000,-61.92496,-34.04074,-111.09156,-10.96417],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t28:=[[-91.00000,-1.00000,-116.46765,130.34640,-106.66134,-19.61866],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t29:=[[-90.00000,0.00000,-115.46765,131.34640,-105.66134,-18.61866],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t30:=[[-86.00000,4.00000,-111.46765,135.34640,-101.66134,-14.61866],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t31:=[[-90.00000,0.00000,-115.46765,131.34640,-105.66134,-18.61866],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t32:=[[-91.00000,-1.00000,-216.48393,73.67778,-111.60339,-127.80898],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t33:=[[-90.00000,0.00000,-215.48393,74.67778,-110.60339,-126.80898],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t34:=[[-86.00000,4.00000,-211.48393,78.67778,-106.60339,-122.80898],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t35:=[[-90.00000,0.00000,-215.48393,74.67778,-110.60339,-126.80898],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t36:=[[-91.00000,-1.00000,-109.86448,-175.83403,-111.48146,-359.90647],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t37:=[[-90.00000,0.00000,-108.86448,-174.83403,-110.48146,-358.90647],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t38:=[[-86.00000,4.00000,-104.86448,-170.83403,-106.48146,-354.90647],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t39:=[[-90.00000,0.00000,-108.86448,-174.83403,-110.48146,-358.90647],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t40:=[[-91.00000,-1.00000,-213.45008,-186.87946,-28.96102,-170.71621],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t41:=[[-90.00000,0.00000,-212.45008,-185.87946,-27.96102,-169.71621],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t42:=[[-86.00000,4.00000,-208.45008,-181.87946,-23.96102,-165.71621],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t43:=[[-90.00000,0.00000,-212.45008,-185.87946,-27.96102,-169.71621],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t44:=[[-91.00000,-1.00000,-181.91020,-91.14159,-105.07792,-269.28151],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t45:=[[-90.00000,0.00000,-180.91020,-90.14159,-104.07792,-268.28151],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t46:=[[-86.00000,4.00000,-176.91020,-86.14159,-100.07792,-264.28151],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t47:=[[-90.00000,0.00000,-180.91020,-90.14159,-104.07792,-268.28151],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t48:=[[-91.00000,-1.00000,-155.05227,-0.01433,-21.42826,-365.90509],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t49:=[[-90.00000,0.00000,-154.05227,0.98567,-20.42826,-364.90509],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t50:=[[-86.00000,4.00000,-150.05227,4.98567,-16.42826,-360.90509],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t51:=[[-90.00000,0.00000,-154.05227,0.98567,-20.42826,-364.90509],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t52:=[[-91.00000,-1.00000,-169.14308,-93.34467,76.96488,-258.84704],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t53:=[[-90.00000,0.00000,-168.14308,-92.34467,77.96488,-257.84704],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t54:=[[-86.00000,4.00000,-164.14308,-88.34467,81.96488,-253.84704],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t55:=[[-90.00000,0.00000,-168.14308,-92.34467,77.96488,-257.84704],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t56:=[[-91.00000,-1.00000,-101.30401,4.75055,96.68552,-182.93996],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t57:=[[-90.00000,0.00000,-100.30401,5.75055,97.68552,-181.93996],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t58:=[[-86.00000,4.00000,-96.30401,9.75055,101.68552,-177.93996],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t59:=[[-90.00000,0.00000,-100.30401,5.75055,97.68552,-181.93996],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t60:=[[-91.00000,-1.00000,-144.29627,75.73441,103.25432,-129.86370],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t61:=[[-90.00000,0.00000,-143.29627,76.73441,104.25432,-128.86370],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t62:=[[-86.00000,4.00000,-139.29627,80.73441,108.25432,-124.86370],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t63:=[[-90.00000,0.00000,-143.29627,76.73441,104.25432,-128.86370],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t64:=[[-91.00000,-1.00000,-187.72480,85.98828,68.06975,-84.43870],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t65:=[[-90.00000,0.00000,-186.72480,86.98828,69.06975,-83.43870],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t66:=[[-86.00000,4.00000,-182.72480,90.98828,73.06975,-79.43870],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t67:=[[-90.00000,0.00000,-186.72480,86.98828,69.06975,-83.43870],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t68:=[[-91.00000,-1.00000,-164.90240,-28.34130,-21.90167,24.69083],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t69:=[[-90.00000,0.00000,-163.90240,-27.34130,-20.90167,25.69083],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t70:=[[-86.00000,4.00000,-159.90240,-23.34130,-16.90167,29.69083],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t71:=[[-90.00000,0.00000,-163.90240,-27.34130,-20.90167,25.69083],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t72:=[[-91.00000,-1.00000,-203.99930,-96.22763,105.75836,64.06562],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t73:=[[-90.00000,0.00000,-202.99930,-95.22763,106.75836,65.06562],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t74:=[[-86.00000,4.00000,-198.99930,-91.22763,110.75836,69.06562],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t75:=[[-90.00000,0.00000,-202.99930,-95.22763,106.75836,65.06562],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t76:=[[-91.00000,-1.00000,-159.16154,-157.46015,21.17470,158.26824],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t77:=[[-90.00000,0.00000,-158.16154,-156.46015,22.17470,159.26824],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t78:=[[-86.00000,4.00000,-154.16154,-152.46015,26.17470,163.26824],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t79:=[[-90.00000,0.00000,-158.16154,-156.46015,22.17470,159.26824],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t80:=[[-91.00000,-1.00000,-68.45016,-67.33374,-105.56872,332.86096],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t81:=[[-90.00000,0.00000,-67.45016,-66.33374,-104.56872,333.86096],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t82:=[[-86.00000,4.00000,-63.45016,-62.33374,-100.56872,337.86096],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t83:=[[-90.00000,0.00000,-67.45016,-66.33374,-104.56872,333.86096],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t84:=[[-91.00000,-1.00000,-12.22582,-158.71063,-14.05595,339.45560],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t85:=[[-90.00000,0.00000,-11.22582,-157.71063,-13.05595,340.45560],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t86:=[[-86.00000,4.00000,-7.22582,-153.71063,-9.05595,344.45560],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t87:=[[-90.00000,0.00000,-11.22582,-157.71063,-13.05595,340.45560],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t88:=[[-91.00000,-1.00000,39.29641,-179.10173,33.32819,363.24481],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t89:=[[-90.00000,0.00000,40.29641,-178.10173,34.32819,364.24481],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t90:=[[-86.00000,4.00000,44.29641,-174.10173,38.32819,368.24481],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t91:=[[-90.00000,0.00000,40.29641,-178.10173,34.32819,364.24481],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t92:=[[-91.00000,-1.00000,-53.21437,-88.51552,88.48241,213.19171],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t93:=[[-90.00000,0.00000,-52.21437,-87.51552,89.48241,214.19171],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t94:=[[-86.00000,4.00000,-48.21437,-83.51552,93.48241,218.19171],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t95:=[[-90.00000,0.00000,-52.21437,-87.51552,89.48241,214.19171],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t96:=[[-91.00000,-1.00000,-48.04041,31.47026,45.11341,163.33163],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t97:=[[-90.00000,0.00000,-47.04041,32.47026,46.11341,164.33163],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t98:=[[-86.00000,4.00000,-43.04041,36.47026,50.11341,168.33163],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t99:=[[-90.00000,0.00000,-47.04041,32.47026,46.11341,164.33163],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t100:=[[-91.00000,-1.00000,-20.16889,93.83039,103.05166,109.98035],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t101:=[[-90.00000,0.00000,-19.16889,94.83039,104.05166,110.98035],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t102:=[[-86.00000,4.00000,-15.16889,98.83039,108.05166,114.98035],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t103:=[[-90.00000,0.00000,-19.16889,94.83039,104.05166,110.98035],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t104:=[[-91.00000,-1.00000,-45.28413,144.10013,-51.82639,382.81968],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t105:=[[-90.00000,0.00000,-44.28413,145.10013,-50.82639,383.81968],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t106:=[[-86.00000,4.00000,-40.28413,149.10013,-46.82639,387.81968],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t107:=[[-90.00000,0.00000,-44.28413,145.10013,-50.82639,383.81968],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t108:=[[-90.00000,-45.00000,-31.60407,79.40106,-109.41682,-298.80311],[9E9,9E9,9E9,9E9,9E9,9E9]];
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
        ! zerocal stage 2: pose 1 of 24, captured from below, then from above
        MoveAbsJ zc_t12,v100 \T:=2.124,fine,tool0;
        MoveAbsJ zc_t13,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t14,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t15,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 2 of 24, captured from below, then from above
        MoveAbsJ zc_t16,v100 \T:=3.912,fine,tool0;
        MoveAbsJ zc_t17,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t18,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t19,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 3 of 24, captured from below, then from above
        MoveAbsJ zc_t20,v100 \T:=2.396,fine,tool0;
        MoveAbsJ zc_t21,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t22,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t23,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 4 of 24, captured from below, then from above
        MoveAbsJ zc_t24,v100 \T:=3.727,fine,tool0;
        MoveAbsJ zc_t25,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t26,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t27,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 5 of 24, captured from below, then from above
        MoveAbsJ zc_t28,v100 \T:=5.090,fine,tool0;
        MoveAbsJ zc_t29,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t30,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t31,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 6 of 24, captured from below, then from above
        MoveAbsJ zc_t32,v100 \T:=4.263,fine,tool0;
        MoveAbsJ zc_t33,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t34,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t35,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 7 of 24, captured from below, then from above
        MoveAbsJ zc_t36,v100 \T:=7.482,fine,tool0;
        MoveAbsJ zc_t37,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t38,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t39,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 8 of 24, captured from below, then from above
        MoveAbsJ zc_t40,v100 \T:=4.837,fine,tool0;
        MoveAbsJ zc_t41,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t42,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t43,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 9 of 24, captured from below, then from above
        MoveAbsJ zc_t44,v100 \T:=3.155,fine,tool0;
        MoveAbsJ zc_t45,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t46,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t47,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 10 of 24, captured from below, then from above
        MoveAbsJ zc_t48,v100 \T:=3.027,fine,tool0;
        MoveAbsJ zc_t49,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t50,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t51,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 11 of 24, captured from below, then from above
        MoveAbsJ zc_t52,v100 \T:=3.229,fine,tool0;
        MoveAbsJ zc_t53,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t54,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t55,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 12 of 24, captured from below, then from above
        MoveAbsJ zc_t56,v100 \T:=3.221,fine,tool0;
        MoveAbsJ zc_t57,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t58,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t59,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 13 of 24, captured from below, then from above
        MoveAbsJ zc_t60,v100 \T:=2.468,fine,tool0;
        MoveAbsJ zc_t61,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t62,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t63,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 14 of 24, captured from below, then from above
        MoveAbsJ zc_t64,v100 \T:=2.087,fine,tool0;
        MoveAbsJ zc_t65,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t66,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t67,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 15 of 24, captured from below, then from above
        MoveAbsJ zc_t68,v100 \T:=3.727,fine,tool0;
        MoveAbsJ zc_t69,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t70,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t71,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 16 of 24, captured from below, then from above
        MoveAbsJ zc_t72,v100 \T:=4.042,fine,tool0;
        MoveAbsJ zc_t73,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t74,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t75,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 17 of 24, captured from below, then from above
        MoveAbsJ zc_t76,v100 \T:=2.901,fine,tool0;
        MoveAbsJ zc_t77,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t78,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t79,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 18 of 24, captured from below, then from above
        MoveAbsJ zc_t80,v100 \T:=4.512,fine,tool0;
        MoveAbsJ zc_t81,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t82,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t83,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 19 of 24, captured from below, then from above
        MoveAbsJ zc_t84,v100 \T:=3.090,fine,tool0;
        MoveAbsJ zc_t85,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t86,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t87,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 20 of 24, captured from below, then from above
        MoveAbsJ zc_t88,v100 \T:=2.321,fine,tool0;
        MoveAbsJ zc_t89,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t90,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t91,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 21 of 24, captured from below, then from above
        MoveAbsJ zc_t92,v100 \T:=4.011,fine,tool0;
        MoveAbsJ zc_t93,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t94,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t95,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 22 of 24, captured from below, then from above
        MoveAbsJ zc_t96,v100 \T:=3.829,fine,tool0;
        MoveAbsJ zc_t97,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t98,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t99,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 23 of 24, captured from below, then from above
        MoveAbsJ zc_t100,v100 \T:=2.228,fine,tool0;
        MoveAbsJ zc_t101,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t102,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t103,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 24 of 24, captured from below, then from above
        MoveAbsJ zc_t104,v100 \T:=6.695,fine,tool0;
        MoveAbsJ zc_t105,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t106,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t107,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal: stage 2 done; the robot parks where the pendant went on the flange (tilted past its
        ! range) for the closing reversal
        MoveAbsJ zc_t108,v100 \T:=15.824,fine,tool0;
        TPWrite "zerocal: closing reversal: take the";
        TPWrite "pendant off the flange to the bench of";
        TPWrite "stage 0, let it capture, turn it 180 deg";
        TPWrite "on the same spot, press OK, let it";
        TPWrite "capture. Then continue.";
        STOP;
        ! zerocal: session done; the pendant shows the result
    ENDPROC
ENDMODULE
