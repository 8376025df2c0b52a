MODULE ServerSocket
  ! Socket task of a remote-controlled cell: receives a command per message, hands
  ! it to the motion task through PERS data and answers when the move is done.
  PERS num nCommand := 0;
  PERS num nMoves := 0;
  VAR socketdev server;
  VAR socketdev client;
  VAR string message := "";
  VAR num code := 0;
  VAR bool ok := FALSE;
  VAR num nBad := 0;

  PROC main()
    SocketCreate server;
    SocketBind server, "127.0.0.1", 1025;
    SocketListen server;
    SocketAccept server, client \Time:=WAIT_MAX;
    WHILE TRUE DO
      SocketReceive client \Str:=message \Time:=WAIT_MAX;
      ok := StrToVal(message, code);
      IF ok AND code >= 1 AND code <= 3 THEN
        WaitUntil nCommand = 0;
        nCommand := code;
        WaitUntil nCommand = 0;
        SocketSend client \Str:="done " + NumToStr(nMoves, 0);
      ELSE
        nBad := (nBad + 1) MOD 3;
        SocketSend client \Str:="bad";
      ENDIF
    ENDWHILE
  ENDPROC
ENDMODULE
