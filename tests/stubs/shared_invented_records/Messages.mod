MODULE Messages
  ! Tests: two buffers of a module not given, each read by a component no known record has
  ! (so each gets a record the stubs invent), are cleared with the same missing value: the
  ! two records become one, with the components of both, so that value fits both buffers.
  ! A missing name assigned whole to a missing array (portsRec := defaultPorts) is an
  ! array of the same size, not a num.
  PROC main()
    FOR i FROM 1 TO 10 DO
      bufRob{1, i} := bmEmpty;
      bufMa{1, i} := bmEmpty;
    ENDFOR
    TPWrite bufRob{1, 1}.msgData;
    TPWrite "seq" \Num:=bufMa{1, 2}.seqNo;
    portsRec{12} := 1024;
    portsRec := defaultPorts;
  ENDPROC
ENDMODULE
