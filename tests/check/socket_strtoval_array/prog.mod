MODULE SocketStrToVal
    ! A client sends "JNT:" followed by five joint values; StrToVal parses them into a
    ! num{5}.  The messages tried hold a well-formed and a malformed array after "JNT:".
    VAR socketdev server;
    VAR socketdev client;
    VAR string text := "";
    VAR num joints{5};
    VAR num state := 0;

    PROC main()
        SocketCreate server;
        SocketBind server, "127.0.0.1", 1025;
        SocketListen server;
        SocketAccept server, client \Time:=WAIT_MAX;
        WHILE TRUE DO
            SocketReceive client \Str:=text \Time:=WAIT_MAX;
            IF StrLen(text) < 5 THEN
                state := 4;
            ELSEIF StrPart(text, 1, 4) = "JNT:" THEN
                IF StrToVal(StrPart(text, 5, StrLen(text) - 4), joints) THEN
                    state := 1;
                ELSE
                    state := 2;
                ENDIF
            ELSE
                state := 3;
            ENDIF
        ENDWHILE
    ENDPROC
ENDMODULE
