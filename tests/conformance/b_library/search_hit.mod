MODULE MainModule
  ! Tests: SearchL stores the search point when the probe signal is seen (in run: the
  ! signal is 1 during the search) and the robot is at the end of the search path.
  PERS robtarget pStart := [[500,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS robtarget pEnd := [[500,0,100],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR robtarget pFound;
  PROC main()
    MoveJ pStart, v500, fine, tool0;
    SearchL \Stop, diProbe, pFound, pEnd, v50, tool0;
    TPWrite "found at z=" \Num:=pFound.trans.z;
    TPWrite "robot at z=" \Num:=CPos(\Tool:=tool0).z;
  ENDPROC
ENDMODULE
