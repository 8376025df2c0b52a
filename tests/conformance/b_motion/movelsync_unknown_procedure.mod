MODULE MainModule
  ! Tests: MoveLSync naming a procedure that does not exist is a run-time error (the name is
  ! only known at run time; error number not asserted).
  CONST robtarget p10 := [[500,100,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    TPWrite "before";
    MoveLSync p10, v100, fine, tool0, "NoSuchProc";
    TPWrite "not reached";
  ENDPROC
ENDMODULE
