MODULE ReplyParse
    ! The reply is searched from its third character: an empty reply puts StrFind's start
    ! outside the string (ERR_ARGVALERR). The step that returns from AskForReply runs on
    ! into the StrFind line (a merged step: the question, passed to a routine that does
    ! nothing with it, is left out of states). The headline names the StrFind line, where
    ! the error is raised, not the ENDPROC the step starts at.
    VAR string reply;
    VAR string question;
    VAR num hash;
    PERS tooldata tGripper := [TRUE, [[0, 0, 100], [1, 0, 0, 0]], [1, [0, 0, 50], [1, 0, 0, 0], 0, 0, 0]];
    CONST robtarget pHome := [[400, 0, 300], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];

    PROC main()
        MoveL pHome, v100, z50, tGripper;
        question := "ready";
        WHILE TRUE DO
            AskForReply question;
            hash := StrFind(reply, 3, "#");
        ENDWHILE
    ENDPROC

    PROC AskForReply(string text)
    ENDPROC
ENDMODULE
