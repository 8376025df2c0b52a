MODULE SocketMatchedWords
    ! A PC drives the cell with text commands: "HOME", "PICK,x,y" and "PAUSE". The server
    ! tells them apart with StrMatch at the message's start, then cuts the coordinates at
    ! each "," and parses them (the pattern of a drawing server found in public code).
    ! The messages tried hold each word alone and each word heading a list of two
    ! numbers ("PICK,1,1"), so every command's code runs in the search.
    VAR socketdev server;
    VAR socketdev client;
    VAR string command := "";
    VAR num x := 0;
    VAR num y := 0;
    VAR num state := 0;

    PROC Pick(string text)
        VAR num first;
        VAR num second;
        first := StrFind(text, 1, ",");
        second := StrFind(text, first + 1, ",");
        IF second > StrLen(text) THEN
            state := -1;
            RETURN;
        ENDIF
        IF StrToVal(StrPart(text, first + 1, second - first - 1), x) AND
                StrToVal(StrPart(text, second + 1, StrLen(text) - second), y) THEN
            state := 2;
        ELSE
            state := -2;
        ENDIF
    ENDPROC

    PROC main()
        SocketCreate server;
        SocketBind server, "127.0.0.1", 1025;
        SocketListen server;
        SocketAccept server, client \Time:=WAIT_MAX;
        WHILE TRUE DO
            SocketReceive client \Str:=command \Time:=WAIT_MAX;
            IF StrMatch(command, 1, "HOME") = 1 THEN
                state := 1;
            ELSEIF StrMatch(command, 1, "PICK,") = 1 THEN
                Pick command;
            ELSEIF StrMatch(command, 1, "PAUSE") = 1 THEN
                state := 3;
            ELSE
                state := 0;
            ENDIF
        ENDWHILE
    ENDPROC
ENDMODULE
