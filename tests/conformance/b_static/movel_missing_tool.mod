MODULE MainModule
  ! Tests: MoveL without its required Tool argument is a static argument error.
  CONST robtarget p10 := [[500,100,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    TPWrite "must not run";
    MoveL p10, v100, z10;
  ENDPROC
ENDMODULE
