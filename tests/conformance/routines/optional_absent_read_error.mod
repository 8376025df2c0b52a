MODULE optional_absent_read_error
  ! Tests: reading an optional parameter that was not supplied raises
  ! ERR_NOTPRES; uncaught, the program stops with exit code 1.
  PROC show(\num Val)
    TPWrite "val=" \Num:=Val;
  ENDPROC
  PROC main()
    show \Val:=1;
    show;
    TPWrite "not reached";
  ENDPROC
ENDMODULE
