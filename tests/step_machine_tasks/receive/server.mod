! Task 1: a server receiving commands (the machine chooses the message and writes it),
! whose client socket is closed and created again after "stop": a receive on a socket that
! is not connected then fails (ERR_SOCK_CLOSED: the machine's guard fails and Python
! raises); a receive with \Time stays Python's (it may time out).
MODULE Server
  VAR socketdev server;
  VAR socketdev client;
  VAR string command := "";
  VAR num received := 0;
  PERS num phase := 0;
  PROC main()
    SocketCreate server;
    SocketBind server, "127.0.0.1", 1025;
    SocketListen server;
    SocketAccept server, client;
    WHILE TRUE DO
      SocketReceive client \Str:=command;
      TEST command
      CASE "go":
        received := (received + 1) MOD 3;
      CASE "stop":
        SocketClose client;
        IF phase = 1 SocketReceive client \Str:=command;
        SocketAccept server, client;
      DEFAULT:
        SocketReceive client \Str:=command \Time:=5;
      ENDTEST
    ENDWHILE
  ENDPROC
ENDMODULE
