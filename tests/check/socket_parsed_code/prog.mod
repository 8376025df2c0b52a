MODULE SocketParsedCode
    ! A PC sends "CODE ID #": the number before the first space is parsed with StrToVal
    ! and dispatched with TEST (the pattern of open_abb-style servers).  The messages
    ! tried put each CASE number before " ", again, and "#" ("1 1 #").
    VAR socketdev server;
    VAR socketdev client;
    VAR string received := "";
    VAR num code := -1;
    VAR num done := 0;

    PROC Parse(string msg)
        VAR num ending;
        VAR num space;
        VAR bool ok;
        ending := StrMatch(msg, 1, "#");
        IF ending > StrLen(msg) THEN
            code := -1;
        ELSE
            space := StrMatch(msg, 1, " ");
            ok := StrToVal(StrPart(msg, 1, space - 1), code);
        ENDIF
    ENDPROC

    PROC main()
        SocketCreate server;
        SocketBind server, "127.0.0.1", 5000;
        SocketListen server;
        SocketAccept server, client \Time:=WAIT_MAX;
        WHILE TRUE DO
            SocketReceive client \Str:=received \Time:=WAIT_MAX;
            Parse received;
            TEST code
            CASE 1:
                done := 1;
            CASE 2:
                done := 2;
            CASE 99:
                done := 99;
            DEFAULT:
                done := -1;
            ENDTEST
        ENDWHILE
    ENDPROC
ENDMODULE
