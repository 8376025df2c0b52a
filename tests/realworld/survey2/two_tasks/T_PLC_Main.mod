MODULE PlcMain
  PERS bool bPartReady := FALSE;
  PROC main()
    bPartReady := TRUE;
  ENDPROC
ENDMODULE
