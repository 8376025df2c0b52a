MODULE RobMain
  PERS bool bPartReady := FALSE;
  PROC main()
    WaitUntil bPartReady;
    TPWrite "picking";
  ENDPROC
ENDMODULE
