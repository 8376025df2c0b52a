MODULE VisionClient
  ! Tests: stubs for a socket client whose connection data lived in another module:
  ! the socket is a VAR socketdev (no value), address and messages are strings.
  VAR string sReply;

  PROC main()
    SocketCreate skCamera;
    SocketConnect skCamera, sCameraIp, nCameraPort \Time:=nTimeout;
    SocketSend skCamera \Str:=sTriggerCmd;
    SocketReceive skCamera \Str:=sReply \Time:=nTimeout;
    IF sReply = sOkReply THEN
      nFound := nFound + 1;
      MoveL RelTool(pCamera, nDx, nDy, 0), v100, fine, tCamera;
    ENDIF
    SocketClose skCamera;
  ENDPROC
ENDMODULE
