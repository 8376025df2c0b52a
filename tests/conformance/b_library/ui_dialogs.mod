MODULE MainModule
  ! Tests: the FlexPendant dialogs of an operator menu (UIMessageBox with \BtnArray,
  ! UINumEntry within \MinValue..\MaxValue, UIListView, UIMsgBox \Result, UIAlphaEntry);
  ! in run each answer is one line of stdin: a button's position, a number, a text.
  VAR btnres nAnswer;
  VAR num nCount;
  VAR num nItem;
  VAR btnres nConfirm;
  VAR string sName;
  CONST listitem liPrograms{3} := [["", "Pallet A"], ["", "Pallet B"], ["", "Service"]];

  PROC main()
    nAnswer := UIMessageBox(\Header:="Cell" \MsgArray:=["What next?", "Choose a mode"]
      \BtnArray:=["Run", "Home", "", "", "Stop"] \Icon:=iconInfo);
    TEST nAnswer
    CASE 1:
      TPWrite "run chosen";
    CASE 2:
      TPWrite "home chosen";
    DEFAULT:
      TPWrite "answer " \Num:=nAnswer;
    ENDTEST
    nCount := UINumEntry(\Header:="Parts" \Message:="How many parts?" \InitValue:=10
      \MinValue:=1 \MaxValue:=50 \AsInteger);
    TPWrite "parts: " \Num:=nCount;
    nItem := UIListView(\Result:=nConfirm \Header:="Program", liPrograms \Icon:=iconInfo);
    TPWrite "item: " + liPrograms{nItem}.text;
    IF nConfirm = resOK TPWrite "confirmed";
    UIMsgBox \Header:="Reset", "Reset the counters?" \Buttons:=btnYesNo \Result:=nConfirm;
    IF nConfirm = resYes TPWrite "reset: yes";
    IF nConfirm = resNo TPWrite "reset: no";
    sName := UIAlphaEntry(\Header:="Batch" \Message:="Batch name" \InitString:="B1");
    TPWrite "batch " + sName;
  ENDPROC
ENDMODULE
