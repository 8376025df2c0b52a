MODULE SocketTestCommands
    ! A server reads a command string and dispatches with TEST on it.
    VAR socketdev server;
    VAR socketdev client;
    VAR string request := "";
    VAR num last := 0;

    PROC main()
        SocketCreate server;
        SocketBind server, "127.0.0.1", 1025;
        SocketListen server;
        SocketAccept server, client \Time:=WAIT_MAX;
        WHILE TRUE DO
            SocketReceive client \Str:=request \Time:=WAIT_MAX;
            Dispatch request;
        ENDWHILE
    ENDPROC

    PROC Dispatch(string command)
        TEST command
        CASE "PNP":
            last := 1;
        CASE "INK":
            last := 2;
        DEFAULT:
            last := 9;
        ENDTEST
        SocketSend client \Str:="ack";
    ENDPROC
ENDMODULE
