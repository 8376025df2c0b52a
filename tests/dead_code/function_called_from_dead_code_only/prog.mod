MODULE Prog
  ! A function whose every call is dead code (after the endless server loop, or in a
  ! routine only such code calls) never runs whatever a client sends, as a procedure so
  ! called does not: Checksum and Twice (called only by Checksum).  Scaled is also called
  ! where a number a client may send leads (7/3: no message tried parses to it): its
  ! warning keeps resting on the messages tried.
  VAR socketdev server;
  VAR socketdev client;
  VAR string command := "";
  VAR num served := 0;
  VAR num value := 0;
  PROC main()
    SocketCreate server;
    SocketBind server, "0.0.0.0", 1025;
    SocketListen server;
    SocketAccept server, client \Time:=WAIT_MAX;
    WHILE TRUE DO
      SocketReceive client \Str:=command \Time:=WAIT_MAX;
      IF StrToVal(command, value) THEN
        IF value * 3 = 7 served := Scaled(value);
      ENDIF
    ENDWHILE
    served := Checksum(value) + Scaled(1);
  ENDPROC
  FUNC num Checksum(num total)
    RETURN Twice(total) + 1;
  ENDFUNC
  FUNC num Twice(num x)
    RETURN 2 * x;
  ENDFUNC
  FUNC num Scaled(num x)
    RETURN 10 * x;
  ENDFUNC
ENDMODULE
