MODULE MainModule
  ! Tests: Offs takes num offsets; a string offset is a static type error.
  CONST robtarget p10 := [[500,100,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    VAR robtarget p;
    TPWrite "must not run";
    p := Offs(p10, "10", 0, 0);
  ENDPROC
ENDMODULE
