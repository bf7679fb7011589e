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
    ! Predicted robot time 8.7 min, the closing reversal included: motion 154 s, dwell 167 s (54
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
    CONST jointtarget zc_t11:=[[-90.00000,-45.00000,-19.16889,94.83039,104.05166,110.98035],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t12:=[[-91.00000,-1.00000,-20.16889,93.83039,103.05166,109.98035],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t13:=[[-90.00000,0.00000,-19.16889,94.83039,104.05166,110.98035],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t14:=[[-86.00000,4.00000,-15.16889,98.83039,108.05166,114.98035],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t15:=[[-90.00000,0.00000,-19.16889,94.83039,104.05166,110.98035],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t16:=[[-91.00000,-1.00000,38.33770,-72.71588,105.86928,309.16743],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t17:=[[-90.00000,0.00000,39.33770,-71.71588,106.86928,310.16743],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t18:=[[-86.00000,4.00000,43.33770,-67.71588,110.86928,314.16743],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t19:=[[-90.00000,0.00000,39.33770,-71.71588,106.86928,310.16743],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t20:=[[-91.00000,-1.00000,-9.85140,-23.31459,11.18972,205.41118],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t21:=[[-90.00000,0.00000,-8.85140,-22.31459,12.18972,206.41118],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t22:=[[-86.00000,4.00000,-4.85140,-18.31459,16.18972,210.41118],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t23:=[[-90.00000,0.00000,-8.85140,-22.31459,12.18972,206.41118],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t24:=[[-91.00000,-1.00000,-12.72495,-95.90371,-74.10257,282.23723],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t25:=[[-90.00000,0.00000,-11.72495,-94.90371,-73.10257,283.23723],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t26:=[[-86.00000,4.00000,-7.72495,-90.90371,-69.10257,287.23723],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t27:=[[-90.00000,0.00000,-11.72495,-94.90371,-73.10257,283.23723],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t28:=[[-91.00000,-1.00000,-42.20674,-113.93601,-58.50880,319.31148],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t29:=[[-90.00000,0.00000,-41.20674,-112.93601,-57.50880,320.31148],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t30:=[[-86.00000,4.00000,-37.20674,-108.93601,-53.50880,324.31148],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t31:=[[-90.00000,0.00000,-41.20674,-112.93601,-57.50880,320.31148],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t32:=[[-91.00000,-1.00000,-76.28306,-106.26379,95.83426,192.93327],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t33:=[[-90.00000,0.00000,-75.28306,-105.26379,96.83426,193.93327],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t34:=[[-86.00000,4.00000,-71.28306,-101.26379,100.83426,197.93327],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t35:=[[-90.00000,0.00000,-75.28306,-105.26379,96.83426,193.93327],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t36:=[[-91.00000,-1.00000,-191.21671,-30.83940,11.51670,386.48673],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t37:=[[-90.00000,0.00000,-190.21671,-29.83940,12.51670,387.48673],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t38:=[[-86.00000,4.00000,-186.21671,-25.83940,16.51670,391.48673],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t39:=[[-90.00000,0.00000,-190.21671,-29.83940,12.51670,387.48673],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t40:=[[-91.00000,-1.00000,-45.28413,144.10013,-51.82639,382.81968],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t41:=[[-90.00000,0.00000,-44.28413,145.10013,-50.82639,383.81968],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t42:=[[-86.00000,4.00000,-40.28413,149.10013,-46.82639,387.81968],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t43:=[[-90.00000,0.00000,-44.28413,145.10013,-50.82639,383.81968],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t44:=[[-91.00000,-1.00000,-167.67732,161.86998,10.03017,196.68202],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t45:=[[-90.00000,0.00000,-166.67732,162.86998,11.03017,197.68202],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t46:=[[-86.00000,4.00000,-162.67732,166.86998,15.03017,201.68202],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t47:=[[-90.00000,0.00000,-166.67732,162.86998,11.03017,197.68202],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t48:=[[-91.00000,-1.00000,-116.46765,130.34640,-106.66134,-19.61866],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t49:=[[-90.00000,0.00000,-115.46765,131.34640,-105.66134,-18.61866],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t50:=[[-86.00000,4.00000,-111.46765,135.34640,-101.66134,-14.61866],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t51:=[[-90.00000,0.00000,-115.46765,131.34640,-105.66134,-18.61866],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t52:=[[-91.00000,-1.00000,-216.48393,73.67778,-111.60339,-127.80898],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t53:=[[-90.00000,0.00000,-215.48393,74.67778,-110.60339,-126.80898],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t54:=[[-86.00000,4.00000,-211.48393,78.67778,-106.60339,-122.80898],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t55:=[[-90.00000,0.00000,-215.48393,74.67778,-110.60339,-126.80898],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t56:=[[-91.00000,-1.00000,-216.79282,77.51682,-103.92885,-126.37356],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t57:=[[-90.00000,0.00000,-215.79282,78.51682,-102.92885,-125.37356],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t58:=[[-86.00000,4.00000,-211.79282,82.51682,-98.92885,-121.37356],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t59:=[[-90.00000,0.00000,-215.79282,78.51682,-102.92885,-125.37356],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t60:=[[-91.00000,-1.00000,-164.90240,-28.34130,-21.90167,24.69083],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t61:=[[-90.00000,0.00000,-163.90240,-27.34130,-20.90167,25.69083],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t62:=[[-86.00000,4.00000,-159.90240,-23.34130,-16.90167,29.69083],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t63:=[[-90.00000,0.00000,-163.90240,-27.34130,-20.90167,25.69083],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t64:=[[-91.00000,-1.00000,-212.68232,-87.14560,-94.47050,123.93326],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t65:=[[-90.00000,0.00000,-211.68232,-86.14560,-93.47050,124.93326],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t66:=[[-86.00000,4.00000,-207.68232,-82.14560,-89.47050,128.93326],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t67:=[[-90.00000,0.00000,-211.68232,-86.14560,-93.47050,124.93326],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t68:=[[-91.00000,-1.00000,-193.64876,86.97330,70.27491,-80.38238],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t69:=[[-90.00000,0.00000,-192.64876,87.97330,71.27491,-79.38238],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t70:=[[-86.00000,4.00000,-188.64876,91.97330,75.27491,-75.38238],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t71:=[[-90.00000,0.00000,-192.64876,87.97330,71.27491,-79.38238],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t72:=[[-91.00000,-1.00000,-114.27282,63.65511,97.30987,-160.34202],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t73:=[[-90.00000,0.00000,-113.27282,64.65511,98.30987,-159.34202],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t74:=[[-86.00000,4.00000,-109.27282,68.65511,102.30987,-155.34202],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t75:=[[-90.00000,0.00000,-113.27282,64.65511,98.30987,-159.34202],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t76:=[[-91.00000,-1.00000,-3.28191,87.68712,101.61005,-275.96986],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t77:=[[-90.00000,0.00000,-2.28191,88.68712,102.61005,-274.96986],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t78:=[[-86.00000,4.00000,1.71809,92.68712,106.61005,-270.96986],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t79:=[[-90.00000,0.00000,-2.28191,88.68712,102.61005,-274.96986],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t80:=[[-91.00000,-1.00000,22.19767,-17.70103,-18.07178,-171.86309],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t81:=[[-90.00000,0.00000,23.19767,-16.70103,-17.07178,-170.86309],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t82:=[[-86.00000,4.00000,27.19767,-12.70103,-13.07178,-166.86309],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t83:=[[-90.00000,0.00000,23.19767,-16.70103,-17.07178,-170.86309],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t84:=[[-91.00000,-1.00000,-55.24097,-107.78937,95.45392,-150.48945],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t85:=[[-90.00000,0.00000,-54.24097,-106.78937,96.45392,-149.48945],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t86:=[[-86.00000,4.00000,-50.24097,-102.78937,100.45392,-145.48945],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t87:=[[-90.00000,0.00000,-54.24097,-106.78937,96.45392,-149.48945],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t88:=[[-91.00000,-1.00000,6.04839,-174.29135,8.17133,-8.79017],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t89:=[[-90.00000,0.00000,7.04839,-173.29135,9.17133,-7.79017],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t90:=[[-86.00000,4.00000,11.04839,-169.29135,13.17133,-3.79017],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t91:=[[-90.00000,0.00000,7.04839,-173.29135,9.17133,-7.79017],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t92:=[[-91.00000,-1.00000,23.14932,-97.08309,-101.44817,-117.81348],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t93:=[[-90.00000,0.00000,24.14932,-96.08309,-100.44817,-116.81348],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t94:=[[-86.00000,4.00000,28.14932,-92.08309,-96.44817,-112.81348],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t95:=[[-90.00000,0.00000,24.14932,-96.08309,-100.44817,-116.81348],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t96:=[[-91.00000,-1.00000,-52.12800,56.15814,-111.42992,-326.25844],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t97:=[[-90.00000,0.00000,-51.12800,57.15814,-110.42992,-325.25844],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t98:=[[-86.00000,4.00000,-47.12800,61.15814,-106.42992,-321.25844],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t99:=[[-90.00000,0.00000,-51.12800,57.15814,-110.42992,-325.25844],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t100:=[[-91.00000,-1.00000,-99.78975,4.64843,-88.50536,-355.56608],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t101:=[[-90.00000,0.00000,-98.78975,5.64843,-87.50536,-354.56608],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t102:=[[-86.00000,4.00000,-94.78975,9.64843,-83.50536,-350.56608],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t103:=[[-90.00000,0.00000,-98.78975,5.64843,-87.50536,-354.56608],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t104:=[[-91.00000,-1.00000,-109.86448,-175.83403,-111.48146,-359.90647],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t105:=[[-90.00000,0.00000,-108.86448,-174.83403,-110.48146,-358.90647],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t106:=[[-86.00000,4.00000,-104.86448,-170.83403,-106.48146,-354.90647],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t107:=[[-90.00000,0.00000,-108.86448,-174.83403,-110.48146,-358.90647],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget zc_t108:=[[-90.00000,-45.00000,-19.16889,94.83039,104.05166,110.98035],[9E9,9E9,9E9,9E9,9E9,9E9]];
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
        MoveAbsJ zc_t16,v100 \T:=5.178,fine,tool0;
        MoveAbsJ zc_t17,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t18,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t19,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 3 of 24, captured from below, then from above
        MoveAbsJ zc_t20,v100 \T:=3.181,fine,tool0;
        MoveAbsJ zc_t21,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t22,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t23,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 4 of 24, captured from below, then from above
        MoveAbsJ zc_t24,v100 \T:=2.921,fine,tool0;
        MoveAbsJ zc_t25,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t26,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t27,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 5 of 24, captured from below, then from above
        MoveAbsJ zc_t28,v100 \T:=1.551,fine,tool0;
        MoveAbsJ zc_t29,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t30,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t31,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 6 of 24, captured from below, then from above
        MoveAbsJ zc_t32,v100 \T:=4.783,fine,tool0;
        MoveAbsJ zc_t33,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t34,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t35,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 7 of 24, captured from below, then from above
        MoveAbsJ zc_t36,v100 \T:=4.933,fine,tool0;
        MoveAbsJ zc_t37,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t38,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t39,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 8 of 24, captured from below, then from above
        MoveAbsJ zc_t40,v100 \T:=5.952,fine,tool0;
        MoveAbsJ zc_t41,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t42,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t43,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 9 of 24, captured from below, then from above
        MoveAbsJ zc_t44,v100 \T:=5.124,fine,tool0;
        MoveAbsJ zc_t45,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t46,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t47,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 10 of 24, captured from below, then from above
        MoveAbsJ zc_t48,v100 \T:=5.483,fine,tool0;
        MoveAbsJ zc_t49,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t50,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t51,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 11 of 24, captured from below, then from above
        MoveAbsJ zc_t52,v100 \T:=4.263,fine,tool0;
        MoveAbsJ zc_t53,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t54,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t55,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 12 of 24, captured from below, then from above
        MoveAbsJ zc_t56,v100 \T:=0.623,fine,tool0;
        MoveAbsJ zc_t57,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t58,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t59,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 13 of 24, captured from below, then from above
        MoveAbsJ zc_t60,v100 \T:=3.989,fine,tool0;
        MoveAbsJ zc_t61,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t62,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t63,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 14 of 24, captured from below, then from above
        MoveAbsJ zc_t64,v100 \T:=2.838,fine,tool0;
        MoveAbsJ zc_t65,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t66,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t67,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 15 of 24, captured from below, then from above
        MoveAbsJ zc_t68,v100 \T:=5.332,fine,tool0;
        MoveAbsJ zc_t69,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t70,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t71,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 16 of 24, captured from below, then from above
        MoveAbsJ zc_t72,v100 \T:=3.393,fine,tool0;
        MoveAbsJ zc_t73,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t74,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t75,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 17 of 24, captured from below, then from above
        MoveAbsJ zc_t76,v100 \T:=4.609,fine,tool0;
        MoveAbsJ zc_t77,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t78,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t79,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 18 of 24, captured from below, then from above
        MoveAbsJ zc_t80,v100 \T:=3.876,fine,tool0;
        MoveAbsJ zc_t81,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t82,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t83,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 19 of 24, captured from below, then from above
        MoveAbsJ zc_t84,v100 \T:=3.649,fine,tool0;
        MoveAbsJ zc_t85,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t86,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t87,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 20 of 24, captured from below, then from above
        MoveAbsJ zc_t88,v100 \T:=3.781,fine,tool0;
        MoveAbsJ zc_t89,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t90,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t91,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 21 of 24, captured from below, then from above
        MoveAbsJ zc_t92,v100 \T:=3.596,fine,tool0;
        MoveAbsJ zc_t93,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t94,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t95,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 22 of 24, captured from below, then from above
        MoveAbsJ zc_t96,v100 \T:=5.309,fine,tool0;
        MoveAbsJ zc_t97,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t98,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t99,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 23 of 24, captured from below, then from above
        MoveAbsJ zc_t100,v100 \T:=2.250,fine,tool0;
        MoveAbsJ zc_t101,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t102,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t103,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal stage 2: pose 24 of 24, captured from below, then from above
        MoveAbsJ zc_t104,v100 \T:=5.565,fine,tool0;
        MoveAbsJ zc_t105,v100 \T:=0.241,fine,tool0;
        WaitTime 3.100;
        MoveAbsJ zc_t106,v100 \T:=0.482,fine,tool0;
        MoveAbsJ zc_t107,v100 \T:=0.482,fine,tool0;
        WaitTime 3.100;
        ! zerocal: stage 2 done; the robot parks where the pendant went on the flange (tilted past its
        ! range) for the closing reversal
        MoveAbsJ zc_t108,v100 \T:=11.096,fine,tool0;
        TPWrite "zerocal: closing reversal: take the";
        TPWrite "pendant off the flange to the bench of";
        TPWrite "stage 0, let it capture, turn it 180 deg";
        TPWrite "on the same spot, press OK, let it";
        TPWrite "capture. Then continue.";
        STOP;
        ! zerocal: session done; the pendant shows the result
    ENDPROC
ENDMODULE
