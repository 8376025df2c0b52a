MODULE IoUnguarded
  VAR socketdev client;
  VAR iodev log;

  PROC main()
    VAR string text;
    SocketCreate client;
    SocketConnect client, "10.0.0.2", 1025;  ! expect: RMC804
    SocketReceive client \Str:=text \Time:=5;
    Open "HOME:" \File:="log.txt", log \Append;  ! expect: RMC804
    Guarded;
    Careful;
    Handled;
  ENDPROC

  PROC Guarded()
    VAR string text;
    SocketReceive client \Str:=text;
  ERROR
    IF ERRNO = ERR_SOCK_CLOSED THEN
      RETURN;
    ENDIF
  ENDPROC

  PROC Careful()
    VAR string text;
    SocketReceive client \Str:=text;  ! expect: RMC804
  ERROR
    IF ERRNO = ERR_DIVZERO THEN
      RETURN;
    ENDIF
  ENDPROC

  PROC Handled()
    Reader;
  ERROR
    RETURN;
  ENDPROC

  PROC Reader()
    VAR string line;
    line := ReadStr(log);
  ENDPROC
ENDMODULE
