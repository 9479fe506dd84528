;;; zero.el --- zero's language server for ISG lists and NC programs, with eglot  -*- lexical-binding: t -*-

;; Emacs 29 and later have eglot built in; Emacs 28 takes it from ELPA (M-x package-install RET eglot)
;; or, on Debian and Ubuntu, from `apt-get install elpa-eglot'.
;;
;; Put this file on the load path and add (require 'zero) to init.el, or load it:
;;
;;   (load "/path/to/zero/editors/emacs/zero.el")
;;   (setq zero-command '("/path/to/.venv/bin/zero" "server"))   ; before the first list is opened
;;
;; Lists (*.lis, *.lst) open in `zero-list-mode', NC programs (*.nc, *.mpf, *.spf) in `zero-nc-mode';
;; both start eglot (`eglot-ensure'), so flymake shows zero's findings as you type, M-. follows a
;; start-up list's paths, C-M-i (`completion-at-point') completes keys and values, M-x eglot-format
;; formats and M-x eglot-code-actions fixes.
;;
;; Completion mid-key: the modes leave `.', `[' and `]' out of words and symbols (as Emacs's plain
;; modes do), so the symbol before point is the word zero's completion items start at:
;; `np_grp[1].achse[0].ve' C-M-i gives `np_grp[1].achse[0].versch'.  (A mode that makes `.[]' symbol
;; characters would match the whole key against items that start after the last `.', and find none.)
;;
;; A server that dies (killed, crashed) is started again by eglot itself: `eglot-autoreconnect'
;; (by default 3) reconnects every buffer of the project when the dead server had run for more than
;; that many seconds.  M-x eglot-reconnect does so by hand.  tests/server/test_emacs.py loads this
;; file as it is.

;; Code pages: a list opens in the code page zero reads it in (`zero-coding-system'): UTF-8 where its
;; bytes are UTF-8 (with the BOM where it has one), else Windows-1252 where every byte is one of its
;; characters, else Latin-1, as zero's list reader decides.  Emacs's own guess for a list in CP850
;; or another DOS code page is `raw-text' or `japanese-shift-jis', whose text eglot cannot send:
;; the server would never hear of the file and flymake would show nothing.  Where zero's
;; configuration declares a code page (`encoding = "cp850"' in [tool.zero]), say the same here:
;;
;;   (setq zero-coding-systems '(("/old-machines/" . cp850)))   ; file-name regexp . coding system
;;
;; Saving writes the buffer back in the code page it was read in, byte for byte.

;;; Code:

(require 'eglot)

(defgroup zero nil
  "zero, the linter for ISG/Beckhoff CNC parameter lists."
  :group 'tools
  :prefix "zero-")

(defcustom zero-command '("zero" "server")
  "The command that starts zero's language server, and its arguments."
  :type '(repeat string))

(defcustom zero-initialization-options nil
  "Server settings sent as initializationOptions, a plist: e.g. (:debounce 250 :machine t)."
  :type 'plist)

(defcustom zero-coding-systems nil
  "Code pages declared for lists, as zero's configuration declares them (`encoding' in [tool.zero]).
An alist of (REGEXP . CODING-SYSTEM): a list or NC program whose file name matches REGEXP opens in
CODING-SYSTEM (e.g. (\"/old-machines/\" . cp850)); any other in the code page zero detects."
  :type '(alist :key-type regexp :value-type coding-system))

(defconst zero-file-regexp "\\.\\(?:lis\\|lst\\|nc\\|mpf\\|spf\\|LIS\\|LST\\|NC\\|MPF\\|SPF\\)\\'"
  "The files zero's modes are for: lists and NC programs.")

(defconst zero--not-in-windows-1252 "[\x81\x8d\x8f\x90\x9d]"
  "The five bytes Windows-1252 gives no character (zero then reads the file as Latin-1).")

(defun zero-detect-coding (file)
  "The coding system zero reads FILE in, by its bytes: UTF-8 (with its signature where the file
starts with a BOM) where they are UTF-8, else Windows-1252 where every byte is one of its
characters, else Latin-1 (src/zero/lists/encoding.py decides the same way)."
  (with-temp-buffer
    (set-buffer-multibyte nil)
    (insert-file-contents-literally file)
    (goto-char (point-min))
    (cond ((looking-at "\xef\xbb\xbf") 'utf-8-with-signature)
          ((not (re-search-forward "[\x80-\xff]" nil t)) 'utf-8)  ; ASCII
          ((let ((text (decode-coding-string (buffer-string) 'utf-8 t)))
             (not (seq-some (lambda (c) (>= c #x3fff80)) text)))  ; no byte left undecoded
           'utf-8)
          ((progn (goto-char (point-min)) (not (re-search-forward zero--not-in-windows-1252 nil t)))
           'windows-1252)
          (t 'latin-1))))

(defun zero-coding-system (arguments)
  "The code page a list or NC program opens in: `zero-coding-systems', else `zero-detect-coding'.
For `file-coding-system-alist': ARGUMENTS are the operation and its arguments; only reading a
file is decided here."
  (when (eq (car arguments) 'insert-file-contents)
    (let ((file (if (consp (nth 1 arguments)) (car (nth 1 arguments)) (nth 1 arguments))))
      (when (and (stringp file) (file-regular-p file))
        (or (assoc-default file zero-coding-systems #'string-match-p)
            (zero-detect-coding file))))))

;;;###autoload
(add-to-list 'file-coding-system-alist (cons zero-file-regexp #'zero-coding-system))

(defvar zero-list-mode-syntax-table
  (let ((table (make-syntax-table)))
    (modify-syntax-entry ?# "<" table)   ; `# comment', to the end of the line
    (modify-syntax-entry ?\n ">" table)
    (modify-syntax-entry ?_ "_" table)   ; part of a key (`np_grp'), as in every plain mode
    (modify-syntax-entry ?. "." table)   ; ends a word: completion starts after it
    (modify-syntax-entry ?\[ "(]" table)
    (modify-syntax-entry ?\] ")[" table)
    (modify-syntax-entry ?\" "." table)
    table)
  "Syntax of a list: `#' starts a comment; `.', `[', `]' end a word.")

(defvar zero-nc-mode-syntax-table
  (let ((table (make-syntax-table)))
    (modify-syntax-entry ?\; "<" table)  ; `; comment', to the end of the line
    (modify-syntax-entry ?\n ">" table)
    (modify-syntax-entry ?_ "_" table)
    (modify-syntax-entry ?. "." table)
    (modify-syntax-entry ?# "." table)   ; `#MACHINE DATA': completion starts after the `#'
    table)
  "Syntax of an NC program: `;' starts a comment; `.', `[', `]', `#' end a word.")

(defconst zero--list-font-lock
  '(("^[ \t]*\\([A-Za-z_][A-Za-z0-9_.]*\\(?:\\[[0-9]*\\][A-Za-z0-9_.]*\\)*\\)" 1 font-lock-variable-name-face)
    ("([^)\n]*)" . font-lock-comment-face))
  "Keys at the start of a line; `( … )' remarks after a value.")

;;;###autoload
(define-derived-mode zero-list-mode prog-mode "ISG-list"
  "Major mode for ISG/Beckhoff CNC parameter lists, with zero's language server."
  :syntax-table zero-list-mode-syntax-table
  (setq-local comment-start "# ")
  (setq-local comment-start-skip "#+[ \t]*")
  (setq-local font-lock-defaults '(zero--list-font-lock)))

;;;###autoload
(define-derived-mode zero-nc-mode prog-mode "ISG-NC"
  "Major mode for ISG NC programs, with zero's language server."
  :syntax-table zero-nc-mode-syntax-table
  (setq-local comment-start "; ")
  (setq-local comment-start-skip ";+[ \t]*"))

(defun zero--contact (&optional _interactive)
  "The command of `zero-command', with `zero-initialization-options'."
  (append zero-command
          (when zero-initialization-options
            (list :initializationOptions zero-initialization-options))))

;;;###autoload
(progn
  (add-to-list 'auto-mode-alist '("\\.\\(?:lis\\|lst\\|LIS\\|LST\\)\\'" . zero-list-mode))
  (add-to-list 'auto-mode-alist '("\\.\\(?:nc\\|mpf\\|spf\\|NC\\|MPF\\|SPF\\)\\'" . zero-nc-mode)))

(with-eval-after-load 'eglot
  (add-to-list 'eglot-server-programs '((zero-list-mode zero-nc-mode) . zero--contact)))

(add-hook 'zero-list-mode-hook #'eglot-ensure)
(add-hook 'zero-nc-mode-hook #'eglot-ensure)

(provide 'zero)

;;; zero.el ends here
