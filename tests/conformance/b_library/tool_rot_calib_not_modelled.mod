MODULE MainModule
  ! Tests: SToolRotCalib loads with its signature (three jointtargets, INOUT tooldata) and
  ! reaching it stops the run with RMC305 (exit 2): it needs the robot's kinematic model.
  PERS tooldata tPen := [TRUE,[[0,0,150],[1,0,0,0]],[1.5,[0,0,60],[1,0,0,0],0,0,0]];
  CONST jointtarget jRef := [[0,0,0,0,90,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    SToolRotCalib jRef, jRef, jRef, tPen;
  ENDPROC
ENDMODULE
