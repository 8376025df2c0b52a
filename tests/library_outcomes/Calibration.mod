MODULE MainModule
  ! Tests: a tool calibration needs the robot's kinematic model: the program loads and runs
  ! up to the call, which stops the run with RMC305 (not a static error).
  PERS tooldata tPen := [TRUE,[[0,0,100],[1,0,0,0]],[0.5,[0,0,20],[1,0,0,0],0,0,0]];
  CONST jointtarget j1 := [[0,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR num nMax;
  VAR num nMean;
  PROC main()
    TPWrite "calibrating";
    MToolTCPCalib j1, j1, j1, j1, tPen, nMax, nMean;
    TPWrite "not reached";
  ENDPROC
ENDMODULE
