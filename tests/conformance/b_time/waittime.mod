MODULE MainModule
  ! Tests: WaitTime waits and then continues with the next instruction (also with \InPos).
  CONST robtarget p10 := [[500,100,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    TPWrite "before";
    WaitTime 0.5;
    TPWrite "after 0.5 s";
    MoveL p10, v100, z10, tool0;
    WaitTime \InPos, 0;
    TPWrite "after InPos";
  ENDPROC
ENDMODULE
